// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap3.h>

#include <span>
#include <utility>
#include <vector>

namespace cgogn::detail
{

using FaceList = std::vector<std::vector<uint32>>;

/// Faces of the supported cells (4 tetrahedron, 5 pyramid, 6 prism,
/// 8 hexahedron) as local vertex numbers, seen counterclockwise from outside
/// (see map_builder.h for the vertex conventions); nullptr for other sizes.
const FaceList* cell_faces(uint32 nb_vertices);
/// Faces of a pyramid / prism on an n-gon (base first), same conventions.
FaceList pyramid_faces(uint32 n);
FaceList prism_faces(uint32 n);

/// One volume as a closed 2-map: a phi1 cycle per face, faces sewn by phi2
/// where a half-edge meets its opposite. `labels[f[i]]` is the vertex label of
/// local vertex f[i]; the label of each new dart's origin is appended to
/// `dart_labels`. Returns the darts, face after face. O(size^2 / faces).
std::vector<Dart> add_volume_topology(CMap3& m, const FaceList& faces, std::span<const uint32> labels,
									  std::vector<uint32>& dart_labels);

/// Closes the phi3 fixed points among `darts` with boundary faces, sewn into
/// boundary volumes; appends the new darts to `created`. New darts get the
/// vertex index of their origin when vertices are indexed. Around each edge,
/// a new boundary face is sewn to the boundary face met by turning through
/// the volumes. After an unsew, `cut` holds the pairs of darts that were
/// phi3-sewn: an older boundary dart whose partner a new face took is then
/// paired with the dart its edge led to through the cut fan, so that the rest
/// of a pinched edge stays one edge; such darts are appended to `repaired`.
void close_phi3_holes(CMap3& m, const std::vector<Dart>& darts, std::vector<Dart>& created,
					  std::span<const std::pair<Dart, Dart>> cut = {}, std::vector<Dart>* repaired = nullptr);

} // namespace cgogn::detail
