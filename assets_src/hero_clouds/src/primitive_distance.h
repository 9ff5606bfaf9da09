#pragma once
// Signed distances (metres; negative inside) and bounding boxes of the recipe's primitives.
// Exact for the sphere, the torus and the tube (a chain of round cones); an estimate for the
// ellipsoid, whose exact distance needs an iterative root find per sample.
#include <glm/glm.hpp>

#include "cloud_recipe.h"

namespace hero_clouds {

struct BoxMetres {
  glm::dvec3 minMetres{0.0};
  glm::dvec3 maxMetres{0.0};
};

double signedDistanceMetres(const PrimitiveShape& shape, glm::dvec3 pointMetres);

// The smallest axis-aligned box holding the primitive.
BoxMetres boundsMetres(const PrimitiveShape& shape);

// The pieces, for tests and for the tube.
double sphereDistance(const SpherePrimitive& sphere, glm::dvec3 p);
// Outside: Quilez's first-order estimate k0 (k0 - 1) / k1 (k0 = |p / r|, k1 = |p / r^2|),
// exact on the surface and close near it. Inside, that estimate grows too deep along the long
// axes of a flat ellipsoid (4000 m out on a disc of radius 4500 m and half-thickness 450 m it
// reads 500 m, where the truth is under 210 m), so the depth is also capped by the distance to
// the surface along each of the three axes, an upper bound on the true depth. Exact for a
// sphere.
double ellipsoidDistance(const EllipsoidPrimitive& ellipsoid, glm::dvec3 p);
// The convex hull of the spheres (a, ra) and (b, rb); the larger sphere when one holds the
// other. Exact (Quilez's round cone).
double roundConeDistance(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, double ra, double rb);
double tubeDistance(const TubePrimitive& tube, glm::dvec3 p);
double torusDistance(const TorusPrimitive& torus, glm::dvec3 p);

}  // namespace hero_clouds
