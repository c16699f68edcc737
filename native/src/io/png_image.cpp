// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/png_image.hpp"

#include <png.h>

#include <cstring>
#include <map>
#include <memory>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/atomic_file.hpp"

namespace ft::io {
namespace {

// libpng reports errors by longjmp to the setjmp in the calling function; we
// throw only after the jump has landed there, outside any libpng frame.
void on_warning(png_structp, png_const_charp) {}
// Keeps libpng's reason for the error message (instead of printing it on
// stderr) and jumps back to the setjmp.
void on_error(png_structp png, png_const_charp message) {
  if (auto* reason = static_cast<std::string*>(png_get_error_ptr(png))) *reason = message;
  png_longjmp(png, 1);
}

struct MemoryReader {
  const std::string* bytes;
  size_t pos;
};

void read_from_memory(png_structp png, png_bytep out, png_size_t n) {
  auto* r = static_cast<MemoryReader*>(png_get_io_ptr(png));
  if (r->pos + n > r->bytes->size()) png_error(png, "unexpected end of file");
  std::memcpy(out, r->bytes->data() + r->pos, n);
  r->pos += n;
}

// libpng allocates a chunk's claimed length before reading it, so a 300-byte
// file claiming a 1 GiB chunk cost 1 GiB and seconds of memset (found by
// fuzzing). The whole file is in memory: every chunk up to IEND must fit in
// it, which bounds what libpng can be asked to allocate by the file's size.
void check_chunk_lengths(const std::string& bytes, const std::string& name) {
  size_t pos = 8;
  while (bytes.size() - pos >= 8) {
    const auto* b = reinterpret_cast<const uint8_t*>(bytes.data() + pos);
    const uint64_t length = (uint64_t(b[0]) << 24) | (uint64_t(b[1]) << 16) | (uint64_t(b[2]) << 8) | b[3];
    if (length + 12 > bytes.size() - pos)
      fail(FT_ERR_FORMAT, "'" + name + "' is a damaged PNG file: a chunk of " + std::to_string(length) +
                              " bytes runs past the end of the file");
    if (std::memcmp(b + 4, "IEND", 4) == 0) return;
    pos += size_t(length) + 12;
  }
}

// Owns libpng's read structs, so that every way out of decode_png (our own
// errors included, thrown after png_read_info) frees them.
struct ReadStructs {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~ReadStructs() { png_destroy_read_struct(&png, &info, nullptr); }
};

}  // namespace

namespace {

// The one libpng writer: an image of `height` rows, row y's bytes from
// row_at(y), written atomically. libpng's errors jump back here and become
// FT_ERR_IO with libpng's reason.
template <class RowAt>
void write_png_rows(const std::string& path, int32_t width, int32_t height, int color_type, int bit_depth,
                    const std::map<std::string, std::string>& text, RowAt&& row_at,
                    PngEffort effort = PngEffort::normal) {
  AtomicFile out(path);
  std::string reason;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &reason, on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    fail(FT_ERR_OUT_OF_MEMORY, "libpng could not start a writer");
  }
  std::vector<png_text> texts;
  for (auto& [k, v] : text) {
    png_text t{};
    t.compression = PNG_TEXT_COMPRESSION_NONE;
    t.key = const_cast<char*>(k.c_str());
    t.text = const_cast<char*>(v.c_str());
    texts.push_back(t);
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    fail(FT_ERR_IO, "writing '" + path + "' failed: " + reason);
  }
  png_init_io(png, out.file());
  // Heightmaps compress poorly at high levels; level 3 is ~3x faster than 6
  // for a 2% larger file.
  png_set_compression_level(png, effort == PngEffort::fast ? 1 : 3);
  // Up alone: a smooth surface's rows differ little, and trying all five
  // filters per row (libpng's default) costs more than the deflate itself.
  if (effort == PngEffort::fast) png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  png_set_IHDR(png, info, uint32_t(width), uint32_t(height), bit_depth, color_type, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (!texts.empty()) png_set_text(png, info, texts.data(), int(texts.size()));
  png_write_info(png, info);
  for (int32_t y = 0; y < height; ++y) png_write_row(png, const_cast<png_bytep>(row_at(y)));
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  out.commit();
}

}  // namespace

void write_png(const std::string& path, const GrayImage& image, PngEffort effort) {
  if (image.bit_depth != 8 && image.bit_depth != 16) invalid("PNG bit depth must be 8 or 16");
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != size_t(image.width) * size_t(image.height))
    invalid("PNG image size does not match its pixel count");
  std::vector<uint8_t> row(size_t(image.width) * (image.bit_depth / 8));
  write_png_rows(path, image.width, image.height, PNG_COLOR_TYPE_GRAY, image.bit_depth, image.text,
                 [&](int32_t y) -> const uint8_t* {
                   const uint16_t* src = image.pixels.data() + size_t(y) * image.width;
                   if (image.bit_depth == 16) {
                     for (int32_t x = 0; x < image.width; ++x) {  // PNG stores 16-bit big-endian
                       row[2 * x] = uint8_t(src[x] >> 8);
                       row[2 * x + 1] = uint8_t(src[x]);
                     }
                   } else {
                     for (int32_t x = 0; x < image.width; ++x) row[x] = uint8_t(src[x] > 255 ? 255 : src[x]);
                   }
                   return row.data();
                 },
                 effort);
}

void write_png_rgb(const std::string& path, int32_t width, int32_t height, const uint8_t* rgb) {
  if (width <= 0 || height <= 0 || !rgb) invalid("an RGB PNG needs a positive size and pixel data");
  write_png_rows(path, width, height, PNG_COLOR_TYPE_RGB, 8, {},
                 [&](int32_t y) { return rgb + size_t(y) * size_t(width) * 3; });
}

void write_png_channels(const std::string& path, const ChannelImage& im) {
  static constexpr int kTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                   PNG_COLOR_TYPE_RGB_ALPHA};
  if (im.channels < 1 || im.channels > 4) invalid("a PNG holds 1 to 4 channels, got " + std::to_string(im.channels));
  if (im.bit_depth != 8 && im.bit_depth != 16) invalid("PNG bit depth must be 8 or 16");
  const size_t per_row = size_t(im.width) * size_t(im.channels);
  if (im.width <= 0 || im.height <= 0 || im.samples.size() != per_row * size_t(im.height))
    invalid("PNG image size does not match its sample count");
  std::vector<uint8_t> row(per_row * size_t(im.bit_depth / 8));
  write_png_rows(path, im.width, im.height, kTypes[im.channels - 1], im.bit_depth, {}, [&](int32_t y) {
    const uint16_t* src = im.samples.data() + size_t(y) * per_row;
    for (size_t i = 0; i < per_row; ++i) {
      if (im.bit_depth == 16) {  // big-endian in the file
        row[2 * i] = uint8_t(src[i] >> 8);
        row[2 * i + 1] = uint8_t(src[i]);
      } else {
        row[i] = uint8_t(src[i] > 255 ? 255 : src[i]);
      }
    }
    return static_cast<const uint8_t*>(row.data());
  });
}

namespace {

// The one libpng reader. `gray`: every kind of PNG normalised to one 8- or
// 16-bit gray channel (colour as luma, alpha stripped), its text chunks into
// `text`; otherwise the channels as stored (palette and sub-byte refused).
ChannelImage decode_samples(const std::string& bytes, const std::string& name, bool gray,
                            std::map<std::string, std::string>* text) {
  if (bytes.size() < 8 || png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) != 0)
    fail(FT_ERR_FORMAT, "'" + name + "' is not a PNG file");
  check_chunk_lengths(bytes, name);
  ReadStructs rs;
  std::string reason;
  rs.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &reason, on_error, on_warning);
  if (rs.png) rs.info = png_create_info_struct(rs.png);
  if (!rs.info) fail(FT_ERR_OUT_OF_MEMORY, "libpng could not start a reader");
  png_structp png = rs.png;
  png_infop info = rs.info;
  ChannelImage im;
  std::vector<png_bytep> rows;
  std::vector<uint8_t> raw;
  MemoryReader reader{&bytes, 0};
  if (setjmp(png_jmpbuf(png))) fail(FT_ERR_FORMAT, "'" + name + "' is a damaged PNG file: " + reason);
  png_set_read_fn(png, &reader, read_from_memory);
  png_set_user_limits(png, 1 << 20, 1 << 20);
  png_read_info(png, info);
  const uint32_t w = png_get_image_width(png, info), h = png_get_image_height(png, info);
  const int color = png_get_color_type(png, info);
  int depth = png_get_bit_depth(png, info);
  if (gray) {
    // Normalise every kind of PNG to 8- or 16-bit gray.
    if (color == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (color == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (color & PNG_COLOR_MASK_ALPHA) png_set_strip_alpha(png);
    if (color == PNG_COLOR_TYPE_RGB || color == PNG_COLOR_TYPE_RGB_ALPHA || color == PNG_COLOR_TYPE_PALETTE)
      png_set_rgb_to_gray_fixed(png, 1, -1, -1);
    if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_strip_alpha(png);
    png_read_update_info(png, info);
    depth = png_get_bit_depth(png, info);
    if (png_get_channels(png, info) != 1) fail(FT_ERR_FORMAT, "'" + name + "': unsupported PNG channel layout");
  } else if (color == PNG_COLOR_TYPE_PALETTE || depth < 8) {
    fail(FT_ERR_FORMAT, "'" + name + "': a palette or sub-byte PNG is not a map of channels");
  }
  const int channels = png_get_channels(png, info);
  const size_t rowbytes = png_get_rowbytes(png, info);
  check_allocation(checked_bytes(rowbytes, h, 3), "reading '" + name + "'");
  raw.resize(rowbytes * h);
  rows.resize(h);
  for (uint32_t y = 0; y < h; ++y) rows[y] = raw.data() + y * rowbytes;
  png_read_image(png, rows.data());
  png_read_end(png, info);
  if (text) {
    png_textp chunks = nullptr;
    int count = 0;
    png_get_text(png, info, &chunks, &count);
    for (int i = 0; i < count; ++i)
      if (chunks[i].key && chunks[i].text) (*text)[chunks[i].key] = chunks[i].text;
  }
  im.width = int32_t(w), im.height = int32_t(h), im.channels = channels, im.bit_depth = depth == 16 ? 16 : 8;
  const size_t n = size_t(w) * h * size_t(channels);  // rows are contiguous: rowbytes = w x channels x bytes
  im.samples.resize(n);
  for (size_t i = 0; i < n; ++i)
    im.samples[i] = depth == 16 ? uint16_t((raw[2 * i] << 8) | raw[2 * i + 1]) : raw[i];
  return im;
}

}  // namespace

ChannelImage read_png_channels(const std::string& path) {
  return decode_samples(read_file(path), path, false, nullptr);
}

GrayImage decode_png(const std::string& bytes, const std::string& name) {
  GrayImage img;
  ChannelImage im = decode_samples(bytes, name, true, &img.text);
  img.width = im.width;
  img.height = im.height;
  img.bit_depth = im.bit_depth;
  img.pixels = std::move(im.samples);
  return img;
}

GrayImage read_png(const std::string& path) { return decode_png(read_file(path), path); }

}  // namespace ft::io
