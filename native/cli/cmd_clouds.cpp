// fracterra clouds: Feder's clouds (seed 001) from a heightfield.
#include <memory>

#include "analysis/clouds.hpp"
#include "cli/command.hpp"
#include "core/error.hpp"
#include "io/heightfield_io.hpp"
#include "io/png_image.hpp"

namespace ft::cli {
namespace {

struct CloudsCli {
  std::string in, threshold = "q0.5", out;
  int bits = 8;
};

Registration reg({"clouds",
                  "Clouds from a heightfield (Feder): black below the threshold, above it grey ~ log(elevation)",
                  [](CLI::App& app) -> std::function<int()> {
                    auto c = std::make_shared<CloudsCli>();
                    app.add_option("--in", c->in, kHeightfieldReadHelp)->required();
                    app.add_option("--threshold", c->threshold,
                                   "height below which the sky is black, or a quantile qF with F in [0, 1]")
                        ->capture_default_str();
                    app.add_option("--out", c->out, "output grey .png (an image map for POV-Ray or Blender)")
                        ->required();
                    app.add_option("--bits", c->bits, "bits per sample: 8 or 16")
                        ->check(CLI::IsMember({8, 16}))->capture_default_str();
                    return [c] {
                      const Heightfield hf = read_heightfield(c->in);
                      CloudOptions o;
                      o.threshold = parse_level(c->threshold, "--threshold");
                      o.bit_depth = c->bits;
                      write_png(c->out, clouds_image(hf, o));
                      return 0;
                    };
                  },
                  52});

}  // namespace
}  // namespace ft::cli
