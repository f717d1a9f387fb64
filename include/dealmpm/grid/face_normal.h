#pragma once

#include <deal.II/base/tensor.h>

namespace dealmpm
{
  using namespace dealii;

  /** Unit normal of a (planar) face of the grid, its sign unspecified: from
   * the vertices, so it needs no FEFaceValues. */
  template <typename Face>
  auto
  face_normal(const Face &face)
  {
    constexpr int  dim = Face::AccessorType::space_dimension;
    Tensor<1, dim> normal;
    if constexpr (dim == 2)
      {
        const Tensor<1, dim> edge = face->vertex(1) - face->vertex(0);
        normal[0]                 = edge[1];
        normal[1]                 = -edge[0];
      }
    else
      normal = cross_product_3d(face->vertex(1) - face->vertex(0),
                                face->vertex(2) - face->vertex(0));
    return normal / normal.norm();
  }
} // namespace dealmpm
