// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/exr.hpp"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/atomic_file.hpp"

namespace ft::io {
namespace {

constexpr const char* kWorldSize = "fracterra:world_size";

// OpenEXR reads and writes through these streams, so the bytes of a file are
// in memory: reading is the same for a file and for the fuzzer's input, and
// writing ends in one atomic write.
class MemoryIStream : public Imf::IStream {
 public:
  explicit MemoryIStream(const std::string& bytes) : Imf::IStream("<memory>"), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || uint64_t(n) > bytes_.size() - pos_) throw Iex::InputExc("the file ends early (truncated)");
    std::memcpy(c, bytes_.data() + pos_, size_t(n));
    pos_ += uint64_t(n);
    return pos_ < bytes_.size();
  }
  uint64_t tellg() override { return pos_; }
  void seekg(uint64_t pos) override {
    if (pos > bytes_.size()) throw Iex::InputExc("a seek past the end of the file (truncated)");
    pos_ = pos;
  }

 private:
  const std::string& bytes_;
  uint64_t pos_ = 0;
};

class MemoryOStream : public Imf::OStream {
 public:
  MemoryOStream() : Imf::OStream("<memory>") {}
  void write(const char c[], int n) override {
    if (pos_ + size_t(n) > bytes_.size()) bytes_.resize(pos_ + size_t(n));
    std::memcpy(bytes_.data() + pos_, c, size_t(n));
    pos_ += size_t(n);
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = size_t(pos); }
  const std::string& bytes() const noexcept { return bytes_; }

 private:
  std::string bytes_;
  size_t pos_ = 0;
};

// OpenEXR sizes its tables from the header: bound them to what a heightfield
// may be before any header is read (the memory cap is checked after).
void limit_image_size() {
  static std::once_flag once;
  std::call_once(once, [] {
    Imf::Header::setMaxImageSize(1 << 20, 1 << 20);
    Imf::Header::setMaxTileSize(1 << 16, 1 << 16);
  });
}

const char* pick_channel(const Imf::ChannelList& channels) {
  for (const char* name : {"Y", "Z", "R"})
    if (channels.findChannel(name)) return name;
  return channels.begin() == channels.end() ? nullptr : channels.begin().name();
}

// OpenEXR allocates each attribute's declared size (up to 2 GB) before it
// reads the value: a 609-byte file asking for 50 MB took seconds (a fuzz
// finding). Every header's attributes must fit in the bytes after them;
// where the walk runs out, OpenEXR's own reading reports the damage.
void check_attribute_sizes(const std::string& bytes, const std::string& name) {
  constexpr uint32_t kMultipart = 0x1000;
  if (bytes.size() < 8) return;
  uint32_t version = 0;
  std::memcpy(&version, bytes.data() + 4, 4);
  size_t pos = 8;
  auto string_at = [&](size_t& at) {  // a NUL-terminated string; npos when it does not end
    const size_t end = bytes.find('\0', at);
    if (end == std::string::npos) return std::string::npos;
    const size_t length = end - at;
    at = end + 1;
    return length;
  };
  for (;;) {  // headers: one, or (multipart) until an empty one
    for (;;) {  // attributes: name, type, size, value, until an empty name
      const size_t name_length = string_at(pos);
      if (name_length == std::string::npos) return;
      if (name_length == 0) break;
      if (string_at(pos) == std::string::npos || bytes.size() - pos < 4) return;
      int32_t size = 0;
      std::memcpy(&size, bytes.data() + pos, 4);
      pos += 4;
      if (size < 0 || size_t(size) > bytes.size() - pos)
        fail(FT_ERR_FORMAT, "'" + name + "' is not a readable OpenEXR file: an attribute says it holds " +
                                std::to_string(size) + " bytes, and " + std::to_string(bytes.size() - pos) + " follow");
      pos += size_t(size);
    }
    if (!(version & kMultipart) || pos >= bytes.size() || bytes[pos] == '\0') return;
  }
}

Heightfield decode(const std::string& bytes, const std::string& name) {
  limit_image_size();
  check_attribute_sizes(bytes, name);
  try {
    MemoryIStream stream(bytes);
    Imf::InputFile in(stream);
    const Imath::Box2i window = in.header().dataWindow();
    const int64_t w = int64_t(window.max.x) - window.min.x + 1, h = int64_t(window.max.y) - window.min.y + 1;
    if (w < 1 || h < 1 || w > (1 << 20) || h > (1 << 20))
      fail(FT_ERR_FORMAT, "'" + name + "' has a data window of " + std::to_string(w) + " x " + std::to_string(h));
    const char* channel = pick_channel(in.header().channels());
    if (channel == nullptr) fail(FT_ERR_FORMAT, "'" + name + "' has no channel");
    const Imf::Channel& c = in.header().channels()[channel];
    if (c.xSampling != 1 || c.ySampling != 1)
      fail(FT_ERR_FORMAT, "'" + name + "': channel " + channel + " is subsampled; heights need every sample");
    Heightfield hf{int32_t(w), int32_t(h)};  // checks the memory cap
    Imf::FrameBuffer fb;
    fb.insert(channel, Imf::Slice::Make(Imf::FLOAT, hf.data(), window, sizeof(float), sizeof(float) * size_t(w)));
    in.setFrameBuffer(fb);
    in.readPixels(window.min.y, window.max.y);
    if (const auto* ws = in.header().findTypedAttribute<Imf::DoubleAttribute>(kWorldSize))
      if (std::isfinite(ws->value()) && ws->value() > 0) hf.set_world_size(ws->value());
    return hf;
  } catch (const Error&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    fail(FT_ERR_FORMAT, "'" + name + "' is not a readable OpenEXR file: " + e.what());
  }
}

}  // namespace

Heightfield read_exr(const std::string& path) { return decode(read_file(path), path); }
Heightfield decode_exr(const std::string& bytes) { return decode(bytes, "<memory>"); }

void write_exr(const Heightfield& hf, const std::string& path, const char* channel) {
  check_allocation(checked_bytes(hf.size(), sizeof(float)), "the OpenEXR file in memory");
  std::string bytes;
  try {
    Imf::Header header(hf.width(), hf.height());
    header.compression() = Imf::ZIP_COMPRESSION;
    header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
    if (hf.world_size() > 0) header.insert(kWorldSize, Imf::DoubleAttribute(hf.world_size()));
    MemoryOStream stream;
    {
      Imf::OutputFile out(stream, header);
      Imf::FrameBuffer fb;
      fb.insert(channel, Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(hf.data())), sizeof(float),
                                sizeof(float) * size_t(hf.width())));
      out.setFrameBuffer(fb);
      out.writePixels(hf.height());
    }
    bytes = stream.bytes();
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    fail(FT_ERR_IO, "cannot write the OpenEXR file '" + path + "': " + e.what());
  }
  write_file_atomically(path, bytes);
}

}  // namespace ft::io
