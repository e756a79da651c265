#pragma once
/// \file
/// Tangent frames for meshes that carry none, compatible with MikkTSpace (Mikkelsen 2008,
/// "Simulation of Wrinkled Surfaces Revisited", ch. 4 and its reference implementation's
/// documented behaviour at its default settings): the frame normal maps baked by Substance,
/// Blender, xNormal and Marmoset assume, and the one glTF 2.0 asks for when a mesh has no
/// TANGENT attribute (glTF 2.0 spec, 3.7.2.1).
///
/// Per triangle, the direction of increasing u is found from the texture mapping; at each
/// corner it is projected into the plane of the vertex normal and weighted by the corner's
/// angle (measured in that plane). A vertex's corners are summed in groups: triangles whose
/// mapping preserves orientation and those that mirror it never share a tangent, so a mirror
/// seam keeps two frames. The bitangent's handedness w is +1 where the mapping preserves
/// orientation, -1 where it mirrors it, so that bitangent = w * cross(normal, tangent) points
/// along increasing v.

#include "runtime/Mesh.h"

namespace mxc::rt {

/// Replaces every vertex's tangent by the MikkTSpace-compatible one. Vertices whose corners
/// fall into several groups (mirror seams) are split, so the vertex count can grow; indices
/// are rewritten accordingly and triangles keep their order. Corners that no triangle with a
/// usable mapping reaches (zero texture area, zero area, no texture coordinates) take a group
/// of the same vertex when there is one, else a unit vector perpendicular to the normal, w = +1.
/// Normals must be unit vectors.
void generateTangents(Mesh& mesh);

}  // namespace mxc::rt
