#include <dealmpm/base/lanes.h>
#include <dealmpm/transfer/lattice_blocks.h>
#include <dealmpm/transfer/stencil.h>
#include <dealmpm/transfer/stencil_order.h>

#include <algorithm>
#include <array>
#include <cstdint>

#include "cpdi_within_cell.h"
#include "node_accumulator.h"
#include "stencil_entries.h"

namespace dealmpm
{
  namespace
  {
    /** How far (in unit-cell lengths) a point may lie outside a cell and
     * still count as in it. */
    constexpr double face_tolerance = 1e-12;

    /** How far unit-cell point xi lies outside [0,1]^dim (0 inside). */
    template <int dim>
    inline double
    distance_outside(const Point<dim> &xi)
    {
      double outside = 0;
      for (unsigned int d = 0; d < dim; ++d)
        {
          outside = std::max(outside, -xi[d]);
          outside = std::max(outside, xi[d] - 1.);
        }
      return outside;
    }

    /** Unit-cell coordinates of x in c; for boxes without the general
     * (Newton or matrix) inverse map. */
    template <int dim, bool boxes>
    inline Point<dim>
    unit_point(const GridCell<dim> &c, const Point<dim> &x)
    {
      if (!boxes)
        return c.reference_point(x);
      Point<dim> xi;
      for (unsigned int d = 0; d < dim; ++d)
        xi[d] = (x[d] - c.origin[d]) * c.inverse_jacobian[d][d];
      return xi;
    }

    /**
     * The cell among the particle's (i-th) cell and its neighbours that
     * holds x (the particle's own cell first: most corners are there), or,
     * when none does, the one x is least outside of. Returns x's unit-cell
     * coordinates there and how far outside they are.
     */
    template <int dim, bool boxes>
    inline const GridCell<dim> *
    locate(const BackgroundGrid<dim> &grid,
           const unsigned int         i,
           const Point<dim>          &x,
           Point<dim>                &xi,
           double                    &outside)
    {
      const GridCell<dim> &own = grid.cells[i];
      xi                       = unit_point<dim, boxes>(own, x);
      outside                  = distance_outside(xi);
      if (outside <= face_tolerance)
        return &own;
      // On boxes, the side x lies on names the likely cell.
      if (boxes)
        {
          unsigned int index = 0, stride = 1;
          for (unsigned int d = 0; d < dim; ++d, stride *= 3)
            index += (xi[d] < 0. ? 0 : (xi[d] > 1. ? 2 : 1)) * stride;
          const GridCell<dim> *guess = grid.side_neighbor(i, index);
          if (guess != nullptr)
            {
              const Point<dim> candidate = unit_point<dim, boxes>(*guess, x);
              if (distance_outside(candidate) <= face_tolerance)
                {
                  xi      = candidate;
                  outside = 0;
                  return guess;
                }
            }
        }
      const GridCell<dim> *best = &own;
      for (const unsigned int k : grid.neighbors_of(i))
        {
          const GridCell<dim> *c = &grid.local_cell(k);
          if (c == &own)
            continue;
          const Point<dim> candidate = unit_point<dim, boxes>(*c, x);
          const double     d         = distance_outside(candidate);
          if (d < outside)
            {
              best    = c;
              xi      = candidate;
              outside = d;
              if (d <= face_tolerance)
                break;
            }
        }
      return best;
    }

    /**
     * The cells the corners of one particle domain lie in, each once, with
     * the sums over its corners c of N_v(x_c) / 2^dim (N) and of N_v(x_c)
     * R^{-T} s_c / 2^dim (G) per vertex v of the cell: a domain's corners
     * often share cells, and each cell's nodes are then gathered once.
     */
    template <int dim>
    struct CornerSums
    {
      static constexpr unsigned int n_corners = GridCell<dim>::n_vertices;

      void
      clear()
      {
        n_cells = 0;
      }

      /** The corner at unit-cell point @p xi of cell @p c, with @p g its
       * R^{-T} s_c / 2^dim. */
      DEAL_II_ALWAYS_INLINE void
      add(const GridCell<dim> *c, const Point<dim> &xi, const Tensor<1, dim> &g)
      {
        unsigned int j = 0;
        while (j < n_cells && cells[j] != c)
          ++j;
        if (j == n_cells)
          {
            cells[n_cells++] = c;
            for (unsigned int v = 0; v < n_corners; ++v)
              {
                N[j][v] = 0;
                G[j][v] = Tensor<1, dim>();
              }
          }
        double N_corner[n_corners];
        q1_values<dim>(xi, N_corner, nullptr);
        for (unsigned int v = 0; v < n_corners; ++v)
          {
            N[j][v] += N_corner[v] / n_corners;
            G[j][v] += N_corner[v] * g;
          }
      }

      const GridCell<dim> *cells[n_corners];
      double               N[n_corners][n_corners];
      Tensor<1, dim>       G[n_corners][n_corners];
      unsigned int         n_cells = 0;
    };

    /** R, whose columns are the domain's half-edge vectors r_d = F e_d l_d:
     * the initial half-lengths l_d carried along by the deformation. */
    template <int dim>
    DEAL_II_ALWAYS_INLINE inline Tensor<2, dim>
    domain_half_edges(const ArrayView<const double> &props, const CoreFields &f)
    {
      const Tensor<2, dim> F = read_tensor<dim>(&props[f.deformation_gradient]);
      Tensor<2, dim>       R;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int d = 0; d < dim; ++d)
          R[a][d] = F[a][d] * props[f.domain_half_length + d];
      return R;
    }

    /** Only the first failing particle is recorded: the run stops with its
     * message. */
    template <int dim>
    void
    record_failure(Stencil<dim>               &stencil,
                   const types::particle_index id,
                   const Point<dim>           &x)
    {
      if (stencil.failed)
        return;
      stencil.failed          = true;
      stencil.failed_particle = id;
      stencil.failed_location = x;
      stencil.failure = "its CPDI domain reaches past the cells next to its "
                        "own (stretched to more than a cell, or far past the "
                        "grid's boundary); use more particles per cell or "
                        "cpGIMP";
    }

    /** The lattice nodes a domain's corners reached: bit n for node n. */
    struct UsedNodes
    {
      std::uint64_t nodes = 0;

      DEAL_II_ALWAYS_INLINE void
      start()
      {
        nodes = 0;
      }

      /** f(n) for each node n used, in lattice order. */
      template <typename Function>
      DEAL_II_ALWAYS_INLINE void
      each(Function &&f) const
      {
        for (std::uint64_t left = nodes; left != 0; left &= left - 1)
          f(static_cast<unsigned int>(__builtin_ctzll(left)));
      }
    };

    /**
     * One domain's sums on the 4^dim lattice around its cell: of
     * N_v(x_c) / 2^dim (N) and of N_v(x_c) R^{-T} s_c / 2^dim (G) over its
     * corners c, by lattice node, (N, G) as one vector of four (in 2D the
     * fourth lane unused); the nodes some corner reached are a bit mask.
     * append_sums() hands them to the stencil, discard_sums() drops them;
     * both zero the nodes used (take()), so that the sums are zero between
     * particles: clearing all of them for each particle became `rep stos`,
     * whose start-up costs more (3D: 27 nodes at most are zeroed where
     * clearing all took 64 vectors).
     */
    template <int dim>
    struct NodeSums : UsedNodes
    {
      static constexpr unsigned int n_nodes   = Utilities::pow(4, dim);
      static constexpr unsigned int n_corners = GridCell<dim>::n_vertices;

      NodeSums()
      {
        for (unsigned int n = 0; n < n_nodes; ++n)
          store_lanes(S[n], Lanes4{});
      }

      /** Node @p n's sums into @p N_n and @p grad_N, and zeroed. */
      DEAL_II_ALWAYS_INLINE void
      take(const unsigned int n, double &N_n, Tensor<1, dim> &grad_N)
      {
        const Lanes4 sums = load_lanes<Lanes4>(S[n]);
        N_n               = sums[0];
        for (unsigned int d = 0; d < dim; ++d)
          grad_N[d] = sums[1 + d];
        store_lanes(S[n], Lanes4{});
      }

    protected:
      /** Adds lane @p v of the weights @p w times @p scale (1 / n_corners,
       * g) to the sums at @p s. */
      DEAL_II_ALWAYS_INLINE static void
      add_vertex(double            *s,
                 const unsigned int v,
                 const Lanes4      &w,
                 const Lanes4      &scale)
      {
        using Index      = long long __attribute__((vector_size(32)));
        const Lanes4 w_v = __builtin_shuffle(w, Index{v, v, v, v} + Index{});
        store_lanes(s, load_lanes<Lanes4>(s) + w_v * scale);
      }

    public:
      alignas(64) double S[n_nodes][4];
    };

    /** A corner's weights into its cell's nodes of NodeSums: the 2^dim
     * weights are products of the corner's 1D factors (those of
     * q1_values()), each broadcast into its vertex's sums. */
    template <int dim>
    struct LatticeSums;

    /** Summed by rows of two along x (three pairs a row) the 2D CPDI
     * column cost 1,028.0 instructions a particle-step instead of 985.0
     * (callgrind). */
    template <>
    struct LatticeSums<2> : NodeSums<2>
    {
      static constexpr std::uint64_t cell_nodes = 0x33;

      /** The corner at unit-cell point @p xi of the cell whose vertex 0
       * is lattice node @p base, with @p g its R^{-T} s_c / 2^dim. */
      DEAL_II_ALWAYS_INLINE void
      add_corner(const unsigned int base, const Lanes2 &xi, const Lanes2 &g)
      {
        const Lanes2 one_xi = 1. - xi;
        // (1 - xi_0, xi_0, 1 - xi_0, xi_0) (1 - xi_1, 1 - xi_1, xi_1, xi_1)
        const Lanes4 w = __builtin_shufflevector(one_xi, xi, 0, 2, 0, 2) *
                         __builtin_shufflevector(one_xi, xi, 1, 1, 3, 3);
        // 1 / n_corners is a power of two: multiplying is dividing.
        const Lanes2 quarter = {1. / n_corners, 0.};
        const Lanes4 scale   = __builtin_shufflevector(quarter, g, 0, 2, 3, 1);
        // The vertices at constant distances from vertex 0's sums (an
        // index base + a + ... is recomputed for each: unsigned sums).
        double *const s0 = S[base];
        for (unsigned int v = 0; v < 4; ++v)
          add_vertex(s0 + 4 * ((v & 1u) + 4 * (v >> 1)), v, w, scale);
        nodes |= cell_nodes << base;
      }
    };

    /** Summed by rows of two along x (four pairs a row) the 3D CPDI column
     * cost 3,364.3 instructions a particle-step instead of 2,972.1
     * (callgrind, before the corners' weights became vectors). */
    template <>
    struct LatticeSums<3> : NodeSums<3>
    {
      static constexpr std::uint64_t cell_nodes = 0x330033;

      /** As LatticeSums<2>::add_corner(), @p xi and @p g with a fourth
       * lane. The 8 weights are two vectors, (f_0 f_1) f_2 by vertex. */
      DEAL_II_ALWAYS_INLINE void
      add_corner(const unsigned int base, const Lanes4 &xi, const Lanes4 &g)
      {
        using Index         = long long __attribute__((vector_size(32)));
        const Lanes4 one_xi = 1. - xi;
        // (1 - xi_0, xi_0, 1 - xi_0, xi_0) (1 - xi_1, 1 - xi_1, xi_1, xi_1)
        const Lanes4 f01 = __builtin_shuffle(one_xi, xi, Index{0, 4, 0, 4}) *
                           __builtin_shuffle(one_xi, xi, Index{1, 1, 5, 5});
        const Lanes4 w[2] = {f01 * one_xi[2], f01 * xi[2]};
        const Lanes4 scale =
          __builtin_shuffle(g, Lanes4{} + 1. / n_corners, Index{4, 0, 1, 2});
        double *const s0 = S[base];
        for (unsigned int c = 0; c < 2; ++c)
          for (unsigned int v = 0; v < 4; ++v)
            add_vertex(s0 + 4 * ((v & 1u) + 4 * (v >> 1) + 16 * c),
                       v,
                       w[c],
                       scale);
        nodes |= cell_nodes << base;
      }
    };

    /** Drops the sums of the nodes @p sums used. */
    template <int dim>
    DEAL_II_ALWAYS_INLINE inline void
    discard_sums(LatticeSums<dim> &sums)
    {
      double         N;
      Tensor<1, dim> grad_N;
      sums.each([&](const unsigned int n)
                  DEAL_II_ALWAYS_INLINE { sums.take(n, N, grad_N); });
    }

    /** @p sums as entries e, ... of @p stencil, the nodes in lattice order
     * (@p block: the lattice's nodes). */
    template <int dim>
    DEAL_II_ALWAYS_INLINE inline void
    append_sums(LatticeSums<dim>   &sums,
                const unsigned int *block,
                std::size_t        &e,
                Stencil<dim>       &stencil)
    {
      make_room_for_entries(stencil, e + __builtin_popcountll(sums.nodes));
      sums.each([&](const unsigned int n) DEAL_II_ALWAYS_INLINE {
        stencil.node[e] = block[n];
        sums.take(n, stencil.N[e], stencil.grad_N[e]);
        ++e;
      });
    }

    /** A point of dim coordinates as one vector (3D: a fourth lane, 0),
     * and the mask a comparison of two gives. */
    template <int dim>
    struct PointLanes;
    template <>
    struct PointLanes<2>
    {
      using type = Lanes2;
      using mask = long long __attribute__((vector_size(16)));
    };
    template <>
    struct PointLanes<3>
    {
      using type = Lanes4;
      using mask = long long __attribute__((vector_size(32)));
    };

    /** The lanes of @p v (3D: the fourth 0). */
    template <int dim, typename Vector>
    DEAL_II_ALWAYS_INLINE inline typename PointLanes<dim>::type
    lanes_of(const Vector &v)
    {
      typename PointLanes<dim>::type lanes = {};
      for (unsigned int d = 0; d < dim; ++d)
        lanes[d] = v[d];
      return lanes;
    }

    /** 3^d by direction d: a patch cell's side index from its sides. */
    template <int dim>
    DEAL_II_ALWAYS_INLINE inline typename PointLanes<dim>::type
    side_stride()
    {
      if constexpr (dim == 2)
        return Lanes2{1., 3.};
      else
        return Lanes4{1., 3., 9., 0.};
    }

    /** The lattice node of vertex 0 of each cell of a patch, by the
     * cell's side index sum_d side_d 3^d: sum_d side_d 4^d. */
    template <int dim>
    constexpr std::array<unsigned char, Utilities::pow(3, dim)>
    lattice_base_of_side()
    {
      std::array<unsigned char, Utilities::pow(3, dim)> base{};
      for (unsigned int side = 0; side < base.size(); ++side)
        for (unsigned int d = 0, s = side, b = 1; d < dim; ++d, s /= 3, b *= 4)
          base[side] += (s % 3) * b;
      return base;
    }

    /** A domain on its cell's lattice, as vectors: the columns of R (x_c
     * = x + sum_e s_e R e_e), x, and the cell's origin and diagonal inverse
     * Jacobian K (3D: fourth lanes 0). */
    template <int dim>
    struct DomainLanes
    {
      using V = typename PointLanes<dim>::type;

      DEAL_II_ALWAYS_INLINE
      DomainLanes(const GridCell<dim>  &own,
                  const Point<dim>     &location,
                  const Tensor<2, dim> &R)
        : x(lanes_of<dim>(location))
        , origin(lanes_of<dim>(own.origin))
        , K{}
      {
        for (unsigned int e = 0; e < dim; ++e)
          {
            R_column[e] = V{};
            for (unsigned int d = 0; d < dim; ++d)
              R_column[e][d] = R[d][e];
            K[e] = own.inverse_jacobian[e][e];
          }
      }

      V R_column[dim];
      V x, origin, K;
    };

    /**
     * Particle k's entries on the lattice @p block of its cell @p own (an
     * axis-aligned box): each corner's Q1 values in the lattice cell that
     * holds it, summed by lattice node, the nodes in lattice order. False
     * (nothing appended) when a corner lies outside the cells of its patch.
     * A corner's coordinates are located as one vector: the same numbers
     * as direction by direction (x + R s, then (x_c - origin) K_dd), with
     * one comparison for all directions.
     */
    template <int dim>
    DEAL_II_ALWAYS_INLINE inline bool
    append_on_lattice(const unsigned int     *block,
                      const std::uint32_t     present,
                      const DomainLanes<dim> &domain,
                      const Tensor<2, dim>   &R_inverse_transpose,
                      const std::size_t       k,
                      LatticeSums<dim>       &sums,
                      std::size_t            &e,
                      Stencil<dim>           &stencil)
    {
      using V                          = typename PointLanes<dim>::type;
      using Mask                       = typename PointLanes<dim>::mask;
      constexpr unsigned int n_corners = GridCell<dim>::n_vertices;
      static constexpr auto  base_of   = lattice_base_of_side<dim>();
      const V(&R_column)[dim]          = domain.R_column;
      // Columns of R^-T: g_c = sum_e s_e R^-T e_e / 2^dim.
      V Q_column[dim];
      for (unsigned int e = 0; e < dim; ++e)
        {
          Q_column[e] = V{};
          for (unsigned int d = 0; d < dim; ++d)
            Q_column[e][d] = R_inverse_transpose[d][e];
        }
      const V &K = domain.K, &origin = domain.origin, &x_lanes = domain.x;
      sums.start();
#pragma GCC unroll 8
      for (unsigned int corner = 0; corner < n_corners; ++corner)
        {
          // s_e R e_e summed in increasing e, as R * s sums (s_e = +-1).
          const auto signed_sum = [corner](const V(&column)[dim]) {
            V sum = (corner & 1u) ? column[0] : -column[0];
            for (unsigned int e = 1; e < dim; ++e)
              sum += ((corner >> e) & 1u) ? column[e] : -column[e];
            return sum;
          };
          const V t = (x_lanes + signed_sum(R_column) - origin) * K;
          // NaN fails here too.
          const Mask inside = (t >= -1.) & (t <= 2.);
          // A corner on a face of its particle's cell (to round-off, as
          // in locate()) counts as in that cell. A domain that fills
          // part of its cell (at rest) then has only that cell's
          // nodes, not the zero weights of a neighbour's as well, and
          // at the grid's upper faces it needs no cell beyond them.
          const Mask below = t < -face_tolerance;
          const Mask above = t > 1. + face_tolerance;
          const V    offset =
            V(below & Mask(V{} - 1.)) + V(above & Mask(V{} + 1.));
          const V xi = t - offset;
          // The cell's side index sum_d (offset_d + 1) 3^d, summed as
          // doubles (exact), 32 more for each coordinate out of range.
          const V side_terms =
            (offset + 1.) * side_stride<dim>() + V(~inside & Mask(V{} + 32.));
          double side_sum = side_terms[0];
          for (unsigned int d = 1; d < dim; ++d)
            side_sum += side_terms[d];
          const unsigned int side = side_sum;
          if (side >= base_of.size() || !((present >> side) & 1u))
            {
              discard_sums(sums);
              return false;
            }
          // 1 / n_corners is a power of two: multiplying is dividing.
          const V g = signed_sum(Q_column) * (1. / n_corners);
          sums.add_corner(base_of[side], xi, g);
        }
      stencil.begin[k] = e;
      append_sums(sums, block, e, stencil);
      return true;
    }

    /** Lattice node of vertex @p v of a lattice cell from its vertex 0. */
    constexpr unsigned int
    lattice_offset(const unsigned int v)
    {
      return (v & 1u) + 4 * ((v >> 1) & 1u) + 16 * (v >> 2);
    }

    /**
     * Particle k's entries on the lattice @p block of its cell (a box) when
     * all its domain's corners lie in that cell (to round-off, as in
     * append_on_lattice()), in closed form; false otherwise. For an
     * invertible R only (the caller's test): CPDI's gradient is zero where
     * R is not, and the corner path gives that.
     */
    template <int dim>
    DEAL_II_ALWAYS_INLINE inline bool
    append_within_own_cell(const unsigned int     *block,
                           const DomainLanes<dim> &domain,
                           const Tensor<2, dim>   &R,
                           const Tensor<2, dim>   &R_inverse_transpose,
                           const std::size_t       k,
                           std::size_t            &e,
                           Stencil<dim>           &stencil)
    {
      using V                           = typename PointLanes<dim>::type;
      using Mask                        = typename PointLanes<dim>::mask;
      constexpr unsigned int n_vertices = GridCell<dim>::n_vertices;
      // |v|: v without its sign bits.
      const auto magnitude = [](const V &v) {
        return V(Mask(v) & (Mask{} + 0x7fffffffffffffffLL));
      };
      const V centre = (domain.x - domain.origin) * domain.K;
      V       reach  = magnitude(domain.R_column[0]);
      for (unsigned int j = 1; j < dim; ++j)
        reach += magnitude(domain.R_column[j]);
      reach *= domain.K;
      // NaN fails here too.
      const Mask inside = (centre - reach >= -face_tolerance) &
                          (centre + reach <= 1. + face_tolerance);
      for (unsigned int d = 0; d < dim; ++d)
        if (!inside[d])
          return false;
      Point<dim>     xi;
      Tensor<2, dim> R_unit;
      Tensor<1, dim> K;
      for (unsigned int d = 0; d < dim; ++d)
        {
          xi[d]     = centre[d];
          K[d]      = domain.K[d];
          R_unit[d] = R[d] * K[d];
        }
      double         N[n_vertices];
      Tensor<1, dim> grad_N[n_vertices];
      sums_within_cell<dim>(xi, R_unit, R_inverse_transpose, K, N, grad_N);
      static constexpr unsigned int own_base =
        lattice_base_of_side<dim>()[Utilities::pow(3, dim) / 2];
      stencil.begin[k] = e;
      make_room_for_entries(stencil, e + n_vertices);
#pragma GCC unroll 8
      for (unsigned int v = 0; v < n_vertices; ++v, ++e)
        {
          stencil.node[e]   = block[own_base + lattice_offset(v)];
          stencil.N[e]      = N[v];
          stencil.grad_N[e] = grad_N[v];
        }
      return true;
    }

    template <int dim, bool boxes>
    void
    compute(const BackgroundGrid<dim> &grid,
            const ParticleSet<dim>    &particles,
            Stencil<dim>              &stencil,
            const LatticeBlocks<dim>  *lattice)
    {
      constexpr unsigned int n_corners = GridCell<dim>::n_vertices;
      // A corner further than this (in unit-cell lengths) from every cell
      // next to the particle's: the domain has outgrown its neighbourhood.
      constexpr double  max_extrapolation = 0.5;
      const CoreFields &f                 = particles.fields;
      const std::size_t n_local = particles.handler.n_locally_owned_particles();
      stencil.begin.resize(n_local + 1);
      std::size_t e = 0;

      NodeAccumulator<dim> gathered;
      CornerSums<dim>      sums;
      LatticeSums<dim>     lattice_sums;
      const std::size_t    n_visited = for_each_particle_in_stencil_order(
        grid,
        particles,
        [&](const std::size_t k, const auto &p, const GridCell<dim> &own)
          DEAL_II_ALWAYS_INLINE {
            const unsigned int   i = index_in_grid(grid, own);
            const Point<dim>     x = p.get_location();
            const Tensor<2, dim> R =
              domain_half_edges<dim>(p.get_properties(), f);
            const bool           invertible = determinant(R) > 0;
            const Tensor<2, dim> R_inverse_transpose =
              invertible ? transpose(invert(R)) : Tensor<2, dim>();
            const unsigned int *block =
              boxes && lattice ? lattice->of(i) : nullptr;
            if (block != nullptr)
              {
                const DomainLanes<dim> domain(own, x, R);
                if (invertible &&
                    append_within_own_cell(
                      block, domain, R, R_inverse_transpose, k, e, stencil))
                  return;
                if (append_on_lattice(block,
                                      lattice->cells_present(i),
                                      domain,
                                      R_inverse_transpose,
                                      k,
                                      lattice_sums,
                                      e,
                                      stencil))
                  return;
              }
            sums.clear();
            for (unsigned int corner = 0; corner < n_corners; ++corner)
              {
                Tensor<1, dim> sign;
                for (unsigned int d = 0; d < dim; ++d)
                  sign[d] = ((corner >> d) & 1u) ? 1. : -1.;
                Point<dim>           xi;
                double               outside;
                const GridCell<dim> *c =
                  locate<dim, boxes>(grid, i, x + R * sign, xi, outside);
                if (!(outside <= max_extrapolation))
                  record_failure(stencil, p.get_id(), x);
                sums.add(c, xi, R_inverse_transpose * sign / double(n_corners));
              }
            gathered.clear();
            for (unsigned int j = 0; j < sums.n_cells; ++j)
              gathered.add_cell(grid, *sums.cells[j], sums.N[j], sums.G[j]);
            gathered.append_to(stencil, k, e);
          });
      stencil.begin[n_visited] = e;
      AssertThrow(n_visited == n_local, ExcInternalError());
    }
  } // namespace

  template <int dim>
  void
  compute_cpdi_stencil(const BackgroundGrid<dim> &grid,
                       const ParticleSet<dim>    &particles,
                       Stencil<dim>              &stencil,
                       const LatticeBlocks<dim>  *lattice)
  {
    stencil.failed = false;
    if (grid.cartesian)
      compute<dim, true>(grid, particles, stencil, lattice);
    else
      compute<dim, false>(grid, particles, stencil, nullptr);
  }

#define DEALMPM_INSTANTIATE(dim)                                  \
  template void compute_cpdi_stencil(const BackgroundGrid<dim> &, \
                                     const ParticleSet<dim> &,    \
                                     Stencil<dim> &,              \
                                     const LatticeBlocks<dim> *);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
