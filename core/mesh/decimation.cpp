// SPDX-License-Identifier: MIT
#include "mesh/decimation.h"

#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include "util/error.h"

namespace layermod {

TriMesh DecimateMesh(const TriMesh& mesh, std::size_t max_triangles, double max_error_mm) {
  if (max_triangles == 0) throw Error("decimation: max_triangles must be positive");
  if (!(max_error_mm > 0.0)) throw Error("decimation: max_error_mm must be positive");
  if (mesh.n_faces() <= max_triangles) return mesh;
  TriMesh simplified = mesh;
  simplified.request_vertex_status();
  simplified.request_edge_status();
  simplified.request_face_status();
  simplified.request_face_normals();
  simplified.update_face_normals();

  using Decimater = OpenMesh::Decimater::DecimaterT<TriMesh>;
  Decimater decimater(simplified);
  OpenMesh::Decimater::ModQuadricT<TriMesh>::Handle quadric;
  decimater.add(quadric);
  decimater.module(quadric).set_max_err(max_error_mm * max_error_mm);  // squared distance
  OpenMesh::Decimater::ModNormalFlippingT<TriMesh>::Handle no_flips;
  decimater.add(no_flips);
  if (!decimater.initialize()) throw Error("decimation: cannot initialise the decimater");
  decimater.decimate_to_faces(0, max_triangles);
  simplified.garbage_collection();
  simplified.update_normals();
  simplified.release_vertex_status();
  simplified.release_edge_status();
  simplified.release_face_status();
  return simplified;
}

}  // namespace layermod
