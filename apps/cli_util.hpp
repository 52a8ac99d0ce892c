#pragma once
// What the subcommands share: splitting and number parsing of option text (exact where the option is
// exact), the options that several subcommands take (--cell, --source-polygon, --light, seeds, thread
// counts), exact values in ordered JSON, and the one style of progress display (util/progress_bar.hpp,
// drawn only when stderr is a terminal and the user did not ask for quiet).
//
// Errors: std::invalid_argument with a one-line message that starts with the option's name (main prints
// "exactvis SUBCOMMAND: error: MESSAGE" and exits 1).
#include "events/light_source.hpp"
#include "kernel/number_types.hpp"
#include "kernel/scene.hpp"
#include "planar/point2d.hpp"
#include "region/cell_visibility.hpp"
#include "region/convex_polygon_3.hpp"
#include "util/progress_bar.hpp"
#include "util/text_split.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace exactvis::app {

// ---- text: split and trim (util/text_split.hpp)
using exactvis::split;
using exactvis::trim;

// ---- numbers
// The double a complete decimal/scientific literal denotes (nearest double; subnormal results and results
// that round to zero are numbers), or std::nullopt when the text is not such a literal or overflows to
// infinity. `inf`/`nan` literals give their non-finite values (the caller checks finiteness).
std::optional<double> to_double(const std::string& text);
// trim(text) as a finite double; throws "WHAT: 'T' is not a number" / "WHAT: 'T' is not finite".
double parse_double(const std::string& text, const std::string& what);
// trim(text) exactly: "num/den" or an integer as that rational, a decimal literal as the double it denotes.
// Throws "WHAT: 'T' is not a number" (also for num/0) / "WHAT: 'T' is not finite".
Exact parse_exact(const std::string& text, const std::string& what);

// ---- options shared by subcommands
// --cell "X0,Y0,Z0,X1,Y1,Z1": six numbers (decimals or num/den, exact), X0 < X1, Y0 < Y1, Z0 < Z1.
region::RationalBox3 parse_cell(const std::string& text);
// The same for any box option named `what` (e.g. "--box"): messages start with `what`.
region::RationalBox3 parse_box(const std::string& text, const std::string& what);
// --source-polygon "x,y,z;x,y,z;...": a convex planar polygon (region::validate_source_polygon), exact.
region::Polygon3 parse_source_polygon(const std::string& text);
// --light SPEC: the exact name of a scene object, or a polygon "x,y,z;x,y,z;x,y,z[;...]" (finite
// decimals) appended to `scene` (events/light_source.hpp). Throws "--light 'SPEC': problem".
LightSource parse_light(Scene& scene, const std::string& spec);
// A decimal whole number in [0, 2^64 - 1] (a seed); throws "WHAT: 'T' is not a whole number in 0 ..
// 18446744073709551615" or "WHAT: 'T' is out of range (0 .. 18446744073709551615)".
std::uint64_t parse_uint64(const std::string& text, const std::string& what);
// A worker thread count: 0 (all cores) or 1 .. region::kMaxThreads; throws "WHAT: N is not a thread count
// (0 = all cores, or 1 .. 1024)".
int check_thread_count(int threads, const std::string& what);

// --grid "NX,NY,NZ": three whole numbers, each 1 .. 100000, at most 10^8 cells in all. Throws "--grid: need 3
// whole numbers NX,NY,NZ, each 1 .. 100000 ('T')" or "--grid: more than 10^8 cells".
std::array<long, 3> parse_grid(const std::string& text);

// --png-size "WxH": the picture's width and height in pixels, each 16 .. 8192; throws "--png-size: 'T' is
// not WxH with W and H in 16 .. 8192".
std::array<int, 2> parse_png_size(const std::string& text);

// ---- JSON
// An exact value in ordered JSON (the subcommands keep their documented key order): io/json_number.hpp.
nlohmann::ordered_json exact_json(const Exact& x);
nlohmann::ordered_json point_json(const Point2& p);

// ---- progress
// Whether to draw progress: stderr is a terminal and not `quiet`.
bool progress_wanted(bool quiet);

// A progress bar for library calls that report a fraction done through a plain function pointer
// (void (*)(double), the 2D complex and the aspect graph). One at a time per process; callback() is null
// when the bar is disabled.
class FractionProgress {
 public:
  FractionProgress(std::string label, bool enabled);
  ~FractionProgress();
  FractionProgress(const FractionProgress&) = delete;
  FractionProgress& operator=(const FractionProgress&) = delete;
  void (*callback() const)(double);

 private:
  std::unique_ptr<ProgressBar> bar_;
};

}  // namespace exactvis::app
