#pragma once
// A 3-vector over any number type (double for input, Interval for filters, Exact for exact evaluation).
#include <array>

namespace exactvis {

template <class NT>
struct Vec3 {
  NT x, y, z;
  Vec3() : x(0), y(0), z(0) {}
  Vec3(NT a, NT b, NT c) : x(std::move(a)), y(std::move(b)), z(std::move(c)) {}
  template <class Other>
  static Vec3 from(const Vec3<Other>& o) { return Vec3(NT(o.x), NT(o.y), NT(o.z)); }
  const NT& operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  NT& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  friend bool operator==(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
};

template <class NT> Vec3<NT> operator+(const Vec3<NT>& a, const Vec3<NT>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class NT> Vec3<NT> operator-(const Vec3<NT>& a, const Vec3<NT>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class NT> Vec3<NT> operator-(const Vec3<NT>& a) { return {-a.x, -a.y, -a.z}; }
template <class NT> Vec3<NT> operator*(const NT& s, const Vec3<NT>& a) { return {s * a.x, s * a.y, s * a.z}; }
template <class NT> NT dot(const Vec3<NT>& a, const Vec3<NT>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class NT> Vec3<NT> cross(const Vec3<NT>& a, const Vec3<NT>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

using Point3 = Vec3<double>;  // input point: a double triple read as exact rationals

}  // namespace exactvis
