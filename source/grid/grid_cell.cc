#include <dealmpm/grid/background_grid.h>

namespace dealmpm
{
  namespace
  {
    template <int dim>
    void
    q1_gradients(const Point<dim> &xi, Tensor<1, dim> *grad)
    {
      for (unsigned int v = 0; v < GridCell<dim>::n_vertices; ++v)
        for (unsigned int d = 0; d < dim; ++d)
          {
            double g = 1;
            for (unsigned int e = 0; e < dim; ++e)
              {
                const bool upper = (v >> e) & 1u;
                if (e == d)
                  g *= upper ? 1. : -1.;
                else
                  g *= upper ? xi[e] : 1. - xi[e];
              }
            grad[v][d] = g;
          }
    }
  } // namespace

  template <int dim>
  Point<dim>
  GridCell<dim>::real_point(const Point<dim> &xi) const
  {
    Point<dim> x;
    for (unsigned int v = 0; v < n_vertices; ++v)
      {
        double N = 1;
        for (unsigned int d = 0; d < dim; ++d)
          N *= ((v >> d) & 1u) ? xi[d] : 1. - xi[d];
        x += N * vertex(v);
      }
    return x;
  }

  template <int dim>
  Tensor<2, dim>
  GridCell<dim>::inverse_jacobian_at(const Point<dim> &xi) const
  {
    if (affine)
      return inverse_jacobian;
    Tensor<1, dim> grad[n_vertices];
    q1_gradients(xi, grad);
    Tensor<2, dim> J;
    for (unsigned int v = 0; v < n_vertices; ++v)
      J += outer_product(vertex(v), grad[v]);
    return invert(J);
  }

  template <int dim>
  Point<dim>
  GridCell<dim>::reference_point_by_newton(const Point<dim> &x) const
  {
    Point<dim> xi;
    for (unsigned int d = 0; d < dim; ++d)
      xi[d] = 0.5;
    xi += inverse_jacobian_at(xi) * (x - real_point(xi));
    // Newton on the Q1 map; converges in a few steps for convex cells.
    for (unsigned int it = 0; it < 20; ++it)
      {
        // Relative to the unit cell, so far from the origin it still stops.
        const Tensor<1, dim> step =
          inverse_jacobian_at(xi) * (x - real_point(xi));
        xi += step;
        if (step.norm() <= 1e-13)
          break;
      }
    return xi;
  }

  template struct GridCell<2>;
  template struct GridCell<3>;
} // namespace dealmpm
