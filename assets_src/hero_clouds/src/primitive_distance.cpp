#include "primitive_distance.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace hero_clouds {
namespace {

double squaredLength(glm::dvec3 v) {
  return glm::dot(v, v);
}

double sign(double x) {
  return x < 0.0 ? -1.0 : (x > 0.0 ? 1.0 : 0.0);
}

BoxMetres ballBounds(glm::dvec3 centre, glm::dvec3 halfExtent) {
  return {centre - halfExtent, centre + halfExtent};
}

BoxMetres bounds(const SpherePrimitive& s) {
  return ballBounds(s.centreMetres, glm::dvec3(s.radiusMetres));
}

BoxMetres bounds(const EllipsoidPrimitive& e) {
  return ballBounds(e.centreMetres, e.radiiMetres);
}

BoxMetres bounds(const TubePrimitive& t) {
  // The hull of a chain of spheres has the box of the spheres.
  BoxMetres box{glm::dvec3(std::numeric_limits<double>::max()),
                glm::dvec3(std::numeric_limits<double>::lowest())};
  for (std::size_t i = 0; i < t.pointsMetres.size(); ++i) {
    const glm::dvec3 r(t.radiiMetres[i]);
    box.minMetres = glm::min(box.minMetres, t.pointsMetres[i] - r);
    box.maxMetres = glm::max(box.maxMetres, t.pointsMetres[i] + r);
  }
  return box;
}

BoxMetres bounds(const TorusPrimitive& t) {
  // The ring's circle reaches R sqrt(1 - a_j^2) along world axis j; the tube adds r.
  const glm::dvec3 a = t.axis;
  const glm::dvec3 circleReach =
      t.majorRadiusMetres * glm::sqrt(glm::max(glm::dvec3(1.0) - a * a, glm::dvec3(0.0)));
  return ballBounds(t.centreMetres, circleReach + glm::dvec3(t.minorRadiusMetres));
}

}  // namespace

double sphereDistance(const SpherePrimitive& sphere, glm::dvec3 p) {
  return glm::length(p - sphere.centreMetres) - sphere.radiusMetres;
}

double ellipsoidDistance(const EllipsoidPrimitive& ellipsoid, glm::dvec3 p) {
  const glm::dvec3 q = p - ellipsoid.centreMetres;
  const glm::dvec3 r = ellipsoid.radiiMetres;
  const double k0 = glm::length(q / r);
  const double k1 = glm::length(q / (r * r));
  const double minRadius = std::min({r.x, r.y, r.z});
  // At the centre the estimate is 0 / 0; the depth there is the smallest radius.
  if (k1 <= 0.0) return -minRadius;
  const double estimate = k0 * (k0 - 1.0) / k1;
  if (k0 >= 1.0) return estimate;
  double depth = std::min(-estimate, minRadius);
  const double k0Squared = k0 * k0;
  for (glm::length_t j = 0; j < 3; ++j) {
    // Along axis j the surface lies where (q_j + t)^2 / r_j^2 + (the other terms) = 1.
    const double others = k0Squared - (q[j] / r[j]) * (q[j] / r[j]);
    const double surface = r[j] * std::sqrt(std::max(1.0 - others, 0.0));
    depth = std::min(depth, surface - std::abs(q[j]));
  }
  return -depth;
}

double roundConeDistance(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, double ra, double rb) {
  const glm::dvec3 ba = b - a;
  const double l2 = squaredLength(ba);
  const double rr = ra - rb;
  // One sphere inside the other (or both at one point): the hull is the larger sphere.
  if (l2 <= rr * rr) {
    return ra >= rb ? glm::length(p - a) - ra : glm::length(p - b) - rb;
  }
  const double a2 = l2 - rr * rr;
  const double il2 = 1.0 / l2;
  const glm::dvec3 pa = p - a;
  const double y = glm::dot(pa, ba);
  const double z = y - l2;
  const double x2 = squaredLength(pa * l2 - ba * y);
  const double y2 = y * y * l2;
  const double z2 = z * z * l2;
  const double k = sign(rr) * rr * rr * x2;
  if (sign(z) * a2 * z2 > k) return std::sqrt(x2 + z2) * il2 - rb;
  if (sign(y) * a2 * y2 < k) return std::sqrt(x2 + y2) * il2 - ra;
  return (std::sqrt(x2 * a2 * il2) + y * rr) * il2 - ra;
}

double tubeDistance(const TubePrimitive& tube, glm::dvec3 p) {
  // The union of the segments' hulls: the minimum of their exact distances is exact outside
  // and the depth below the nearest segment's surface inside.
  double d = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i + 1 < tube.pointsMetres.size(); ++i) {
    d = std::min(d, roundConeDistance(p, tube.pointsMetres[i], tube.pointsMetres[i + 1],
                                      tube.radiiMetres[i], tube.radiiMetres[i + 1]));
  }
  return d;
}

double torusDistance(const TorusPrimitive& torus, glm::dvec3 p) {
  const glm::dvec3 q = p - torus.centreMetres;
  const double along = glm::dot(q, torus.axis);
  const double across = glm::length(q - along * torus.axis);
  return std::hypot(across - torus.majorRadiusMetres, along) - torus.minorRadiusMetres;
}

double signedDistanceMetres(const PrimitiveShape& shape, glm::dvec3 pointMetres) {
  struct Visitor {
    glm::dvec3 p;
    double operator()(const SpherePrimitive& s) const { return sphereDistance(s, p); }
    double operator()(const EllipsoidPrimitive& e) const { return ellipsoidDistance(e, p); }
    double operator()(const TubePrimitive& t) const { return tubeDistance(t, p); }
    double operator()(const TorusPrimitive& t) const { return torusDistance(t, p); }
  };
  return std::visit(Visitor{pointMetres}, shape);
}

BoxMetres boundsMetres(const PrimitiveShape& shape) {
  return std::visit([](const auto& primitive) { return bounds(primitive); }, shape);
}

}  // namespace hero_clouds
