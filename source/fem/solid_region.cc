#include <deal.II/fe/fe_q.h>

#include <dealmpm/fem/solid_region.h>

namespace dealmpm
{
  template <int dim>
  SolidRegion<dim>::SolidRegion(const MPI_Comm       comm,
                                const Material<dim> &material,
                                const unsigned int   degree)
    : comm(comm)
    , triangulation(comm)
    , fe(FE_Q<dim>(degree), dim)
    , dof_handler(triangulation)
    , material(material)
  {}

  template <int dim>
  Point<dim>
  SolidRegion<dim>::position(const Node &node) const
  {
    return node.X + node_vector(displacement, node);
  }

  template <int dim>
  Tensor<1, dim>
  SolidRegion<dim>::node_vector(
    const LinearAlgebra::distributed::Vector<double> &v,
    const Node                                       &node) const
  {
    Tensor<1, dim> value;
    for (unsigned int d = 0; d < dim; ++d)
      value[d] = v.local_element(node.dof[d]);
    return value;
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  SolidRegion<dim>::area_normals(const std::set<types::boundary_id> &ids) const
  {
    LinearAlgebra::distributed::Vector<double> a(force);
    a = 0;
    displacement.update_ghost_values();
    const ReferenceData &r = reference;
    for (std::size_t face = 0; face < r.face_cell.size(); ++face)
      if (ids.count(r.face_id[face]))
        {
          const unsigned int  c    = r.face_cell[face];
          const unsigned int *dofs = &r.local_dofs[c * r.n_dofs];
          for (unsigned int q = 0; q < r.n_face_q; ++q)
            {
              const std::size_t    k    = face * r.n_face_q + q;
              const Tensor<1, dim> n_da = current_normal_area(face, q);
              const double        *N    = &r.face_value[k * r.n_scalar];
              for (unsigned int i = 0; i < r.n_dofs; ++i)
                a.local_element(dofs[i]) +=
                  N[r.scalar[i]] * n_da[r.component[i]];
            }
        }
    a.compress(VectorOperation::add);
    std::vector<Tensor<1, dim>> normals(nodes.size());
    for (unsigned int k = 0; k < nodes.size(); ++k)
      normals[k] = node_vector(a, nodes[k]);
    return normals;
  }

  template <int dim>
  Tensor<1, dim>
  SolidRegion<dim>::current_normal_area(const std::size_t  face,
                                        const unsigned int q) const
  {
    const ReferenceData &r = reference;
    const std::size_t    k = face * r.n_face_q + q;
    const Tensor<2, dim> F = unit_symmetric_tensor<dim>() +
                             reference_gradient(displacement,
                                                r.face_cell[face],
                                                &r.face_grad[k * r.n_scalar]);
    // Nanson: n da = J F^-T N dA.
    return determinant(F) * transpose(invert(F)) * r.face_normal_dA[k];
  }

  template <int dim>
  void
  SolidRegion<dim>::use_affine()
  {
    affine.resize(dim, velocity);
    for (auto &column : affine)
      column = 0;
  }

  template <int dim>
  Tensor<2, dim>
  SolidRegion<dim>::affine_of(const Node &node) const
  {
    Tensor<2, dim> B;
    for (unsigned int j = 0; j < affine.size(); ++j)
      for (unsigned int c = 0; c < dim; ++c)
        B[c][j] = affine[j].local_element(node.dof[c]);
    return B;
  }

  template <int dim>
  void
  SolidRegion<dim>::set_affine(const Node &node, const Tensor<2, dim> &B)
  {
    for (unsigned int j = 0; j < affine.size(); ++j)
      for (unsigned int c = 0; c < dim; ++c)
        affine[j].local_element(node.dof[c]) = B[c][j];
  }

  template <int dim>
  void
  SolidRegion<dim>::set_bonded_velocities(
    const std::vector<unsigned int>   &bonded,
    const std::vector<Tensor<1, dim>> &v,
    const std::vector<Tensor<2, dim>> &B)
  {
    velocity.zero_out_ghost_values();
    for (auto &column : affine)
      column.zero_out_ghost_values();
    for (std::size_t k = 0; k < bonded.size(); ++k)
      {
        const Node &node = nodes[bonded[k]];
        for (unsigned int c = 0; c < dim; ++c)
          velocity.local_element(node.dof[c]) = v[k][c];
        if (!B.empty())
          set_affine(node, B[k]);
      }
  }

  template <int dim>
  void
  SolidRegion<dim>::set_velocity_corrections(
    const std::vector<unsigned int>   &indices,
    const std::vector<Tensor<1, dim>> &change)
  {
    velocity_correction.assign(nodes.size(), Tensor<1, dim>());
    for (std::size_t j = 0; j < indices.size(); ++j)
      velocity_correction[indices[j]] = change[j];
  }

  template class SolidRegion<2>;
  template class SolidRegion<3>;
} // namespace dealmpm
