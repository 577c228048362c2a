// Rigid pipes (docs/model.md#ring-and-pipe): the gap and the normal of a body point in the
// reference configuration (small displacements, docs/model.md#signorini).
//
// The body (the ring) lies outside the pipe. For a point p, `gap` is the signed distance from the
// pipe's surface (positive outside, negative when p starts inside the pipe, i.e. for an
// interference fit) and `normal` the unit normal of the pipe at the closest point, pointing out of
// the pipe (into the body). Non-penetration, linearised: normal . u + gap >= 0.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

namespace sma {

struct ContactGeometry {
  double gap;
  double nx, ny;  // unit normal out of the pipe
};

// Circular pipe of radius R centred at (cx, cy) (an offset pipe is an offset centre).
inline ContactGeometry circle_gap(double px, double py, double cx, double cy, double R) {
  if (!(R > 0)) throw std::invalid_argument("circle: radius " + std::to_string(R) + " must be > 0");
  const double dx = px - cx, dy = py - cy, d = std::hypot(dx, dy);
  if (d == 0) throw std::invalid_argument("circle: point at the centre has no normal");
  return {d - R, dx / d, dy / d};
}

// Elliptic pipe with semi-axes A (along x) and B (along y), centred at (cx, cy): closest-point
// projection by Newton's method on the angle parameter, started from the radial guess and
// safeguarded by bisection on the stationarity condition over the quadrant of p.
inline ContactGeometry ellipse_gap(double px, double py, double cx, double cy, double A, double B) {
  if (!(A > 0 && B > 0))
    throw std::invalid_argument("ellipse: semi-axes " + std::to_string(A) + ", " + std::to_string(B) +
                                " must be > 0");
  const double x = std::fabs(px - cx), y = std::fabs(py - cy);
  const double sx = (px - cx) < 0 ? -1.0 : 1.0, sy = (py - cy) < 0 ? -1.0 : 1.0;
  // f(t) = d/dt (1/2 |p - q(t)|^2) with q(t) = (A cos t, B sin t), t in [0, pi/2] for x, y >= 0:
  // f(t) = (B^2 - A^2) sin t cos t + A x sin t - B y cos t; f(0) <= 0 <= f(pi/2).
  auto f = [&](double t) { return (B * B - A * A) * std::sin(t) * std::cos(t) + A * x * std::sin(t) - B * y * std::cos(t); };
  auto df = [&](double t) {
    return (B * B - A * A) * std::cos(2 * t) + A * x * std::cos(t) + B * y * std::sin(t);
  };
  // A point on an axis whose closest point is that axis's vertex (not beyond the evolute's cusp,
  // where two points off the axis are closer): the vertex and its normal exactly. Newton's t for
  // pi / 2 leaves cos t = 6e-17, a normal tilted by round-off (n_x = 6e-17 at x = 0), which the
  // 3D model's e_theta rows read as a motion of a held component.
  if (x == 0 && B * y >= B * B - A * A) {
    const double inside = (y / B) * (y / B) - 1.0;
    return {inside < 0 ? -std::fabs(y - B) : std::fabs(y - B), 0.0, sy};
  }
  if (y == 0 && A * x >= A * A - B * B) {
    const double inside = (x / A) * (x / A) - 1.0;
    return {inside < 0 ? -std::fabs(x - A) : std::fabs(x - A), sx, 0.0};
  }
  double lo = 0.0, hi = M_PI / 2;
  double t = std::atan2(A * y, B * x);
  for (int it = 0; it < 100; ++it) {
    const double ft = f(t);
    if (ft == 0) break;
    (ft < 0 ? lo : hi) = t;
    const double d = df(t);
    double next = d != 0 ? t - ft / d : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - t) <= 1e-16 * (1 + std::fabs(t))) { t = next; break; }
    t = next;
  }
  const double qx = A * std::cos(t), qy = B * std::sin(t);
  // Outward normal of the ellipse at q: gradient of (x/A)^2 + (y/B)^2.
  double nx = qx / (A * A), ny = qy / (B * B);
  const double nn = std::hypot(nx, ny);
  nx /= nn;
  ny /= nn;
  const double inside = (x / A) * (x / A) + (y / B) * (y / B) - 1.0;
  const double distance = std::hypot(x - qx, y - qy);
  return {inside < 0 ? -distance : distance, sx * nx, sy * ny};
}

}  // namespace sma
