#pragma once
// How far a polyhedral cone of directions reaches along each axis: for the cone
// {u : u.c <= 0 for every constraint c}, the largest |u_i| over its unit vectors. Bounds the
// boxes that the regions of FeatureRegions sweep within a given distance of their feature.

#include "common/Types.hpp"

#include <vector>

namespace fsi::geometry {

/// For each axis i, max |u_i| over unit vectors u with u.c <= 0 for every c in constraints
/// (0 when only u = 0 satisfies them all), rounded up. Exact up to round-off: the maximum
/// of a linear function over the cone and the unit sphere lies at the axis itself, at the
/// axis projected onto one constraint plane, or on the line where two planes meet, so only
/// those candidates are tried. Cost grows as the cube of the number of constraints.
Vec3 cone_spread(const std::vector<Vec3> &constraints);

} // namespace fsi::geometry
