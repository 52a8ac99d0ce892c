#include "apps/cli_util.hpp"

#include "io/json_number.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace exactvis::app {

std::optional<double> to_double(const std::string& text) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  // ERANGE: overflow (+-HUGE_VAL) is refused; underflow (a subnormal or zero result) is the nearest double.
  if (errno == ERANGE && std::isinf(v)) return std::nullopt;
  return v;
}

double parse_double(const std::string& text, const std::string& what) {
  const std::string t = trim(text);
  const std::optional<double> v = to_double(t);
  if (!v) throw std::invalid_argument(what + ": '" + t + "' is not a number");
  if (!std::isfinite(*v)) throw std::invalid_argument(what + ": '" + t + "' is not finite");
  return *v;
}

Exact parse_exact(const std::string& text, const std::string& what) {
  const std::string t = trim(text);
  if (t.find('/') == std::string::npos) return Exact(parse_double(t, what));
  try {
    return parse_rational(t);
  } catch (const std::exception& e) {
    throw std::invalid_argument(what + ": " + e.what());
  }
}

region::RationalBox3 parse_box(const std::string& text, const std::string& what) {
  const auto parts = split(text, ',');
  if (parts.size() != 6) throw std::invalid_argument(what + " needs 6 numbers X0,Y0,Z0,X1,Y1,Z1");
  region::RationalBox3 b;
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = parse_exact(parts[k], what);
    b.hi[k] = parse_exact(parts[k + 3], what);
    if (!(b.lo[k] < b.hi[k])) throw std::invalid_argument(what + ": need X0 < X1, Y0 < Y1 and Z0 < Z1");
  }
  return b;
}

std::array<long, 3> parse_grid(const std::string& text) {
  const auto parts = split(text, ',');
  const std::string msg = "--grid: need 3 whole numbers NX,NY,NZ, each 1 .. 100000";
  if (parts.size() != 3) throw std::invalid_argument(msg);
  std::array<long, 3> n{};
  for (int k = 0; k < 3; ++k) {
    const std::string t = trim(parts[k]);
    if (t.empty() || t.size() > 6 || t.find_first_not_of("0123456789") != std::string::npos)
      throw std::invalid_argument(msg + " ('" + t + "')");
    n[k] = std::stol(t);
    if (n[k] < 1 || n[k] > 100000) throw std::invalid_argument(msg + " ('" + t + "')");
  }
  if (n[0] * n[1] * n[2] > 100'000'000) throw std::invalid_argument("--grid: more than 10^8 cells");
  return n;
}

region::RationalBox3 parse_cell(const std::string& text) { return parse_box(text, "--cell"); }

region::Polygon3 parse_source_polygon(const std::string& text) {
  region::Polygon3 poly;
  for (const auto& vertex : split(text, ';')) {
    if (trim(vertex).empty()) continue;
    const auto parts = split(vertex, ',');
    if (parts.size() != 3) throw std::invalid_argument("--source-polygon: each vertex needs 3 numbers x,y,z");
    RationalPoint3 p;
    for (int k = 0; k < 3; ++k) p[k] = parse_exact(parts[k], "--source-polygon");
    poly.push_back(p);
  }
  try {
    region::validate_source_polygon(poly);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--source-polygon: ") + e.what());
  }
  return poly;
}

LightSource parse_light(Scene& scene, const std::string& spec) {
  const std::string prefix = "--light '" + spec + "': ";
  try {
    if (std::optional<LightSource> named = light_from_object(scene, spec)) return *named;
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(prefix + e.what());
  }
  if (spec.find(',') == std::string::npos)
    throw std::invalid_argument(prefix + "no scene object has this name, and it is not a polygon "
                                         "'x,y,z;x,y,z;x,y,z'");
  std::vector<Point3> pts;
  for (const auto& p : split(spec, ';')) {
    const auto c = split(p, ',');
    if (c.size() != 3) throw std::invalid_argument(prefix + "point '" + p + "' needs 3 comma-separated coordinates");
    Point3 q;
    for (int k = 0; k < 3; ++k) {
      // Leading and trailing white space is allowed around a coordinate.
      const std::string t = trim(c[k]);
      const std::optional<double> v = t.empty() ? std::nullopt : to_double(t);
      if (!v || !std::isfinite(*v)) throw std::invalid_argument(prefix + "'" + c[k] + "' is not a finite number");
      q[k] = *v;
    }
    pts.push_back(q);
  }
  try {
    return append_light_polygon(scene, pts);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(prefix + e.what());
  }
}

std::uint64_t parse_uint64(const std::string& text, const std::string& what) {
  const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
  if (!digits) throw std::invalid_argument(what + ": '" + text + "' is not a whole number in 0 .. 18446744073709551615");
  // 2^64 - 1 has 20 digits; compare as text after dropping leading zeros.
  const std::string t = text.substr(std::min(text.find_first_not_of('0'), text.size() - 1));
  const std::string max = "18446744073709551615";
  if (t.size() > max.size() || (t.size() == max.size() && t > max))
    throw std::invalid_argument(what + ": '" + text + "' is out of range (0 .. 18446744073709551615)");
  return std::stoull(t);
}

int check_thread_count(int threads, const std::string& what) {
  if (threads < 0 || threads > region::kMaxThreads)
    throw std::invalid_argument(what + ": " + std::to_string(threads) + " is not a thread count (0 = all cores, or 1 .. " +
                                std::to_string(region::kMaxThreads) + ")");
  return threads;
}

std::array<int, 2> parse_png_size(const std::string& text) {
  const std::string t = trim(text);
  const auto x = t.find('x');
  const std::string msg = "--png-size: '" + t + "' is not WxH with W and H in 16 .. 8192";
  if (x == std::string::npos) throw std::invalid_argument(msg);
  std::array<int, 2> size{};
  const std::string parts[2] = {t.substr(0, x), t.substr(x + 1)};
  for (int k = 0; k < 2; ++k) {
    if (parts[k].empty() || parts[k].size() > 4 || parts[k].find_first_not_of("0123456789") != std::string::npos)
      throw std::invalid_argument(msg);
    size[k] = std::stoi(parts[k]);
    if (size[k] < 16 || size[k] > 8192) throw std::invalid_argument(msg);
  }
  return size;
}

nlohmann::ordered_json exact_json(const Exact& x) { return nlohmann::ordered_json(exact_to_json(x)); }

nlohmann::ordered_json point_json(const Point2& p) { return nlohmann::ordered_json::array({exact_json(p.x), exact_json(p.y)}); }

bool progress_wanted(bool quiet) { return !quiet && isatty(STDERR_FILENO); }

namespace {
ProgressBar* active_fraction_bar = nullptr;
constexpr std::uint64_t kFractionSteps = 1000;
void report_fraction(double f) {
  if (!active_fraction_bar) return;
  const double c = std::min(1.0, std::max(0.0, f));
  active_fraction_bar->set_done(static_cast<std::uint64_t>(c * kFractionSteps));
}
}  // namespace

FractionProgress::FractionProgress(std::string label, bool enabled) {
  if (!enabled || active_fraction_bar) return;
  bar_ = std::make_unique<ProgressBar>(std::move(label), kFractionSteps, true);
  active_fraction_bar = bar_.get();
}

FractionProgress::~FractionProgress() {
  if (bar_ && active_fraction_bar == bar_.get()) active_fraction_bar = nullptr;
}

void (*FractionProgress::callback() const)(double) { return bar_ ? report_fraction : nullptr; }

}  // namespace exactvis::app
