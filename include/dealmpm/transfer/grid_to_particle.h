#pragma once

#include <deal.II/base/geometry_info.h>

#include <dealmpm/base/lanes.h>
#include <dealmpm/base/smallest_stretch.h>
#include <dealmpm/grid/background_grid.h>
#include <dealmpm/grid/nodal_field_set.h>
#include <dealmpm/grid/nodal_fields.h>
#include <dealmpm/grid/side_neighbors.h>
#include <dealmpm/particles/particle_set.h>
#include <dealmpm/transfer/affine_transfer.h>
#include <dealmpm/transfer/box_q1.h>
#include <dealmpm/transfer/deformation_update.h>
#include <dealmpm/transfer/formulation.h>
#include <dealmpm/transfer/particle_weights.h>
#include <dealmpm/transfer/remap_in_sweep.h>
#include <dealmpm/transfer/stencil.h>
#include <dealmpm/transfer/stencil_order.h>
#include <dealmpm/transfer/velocity_arrays.h>

#include <algorithm>
#include <functional>
#include <type_traits>
#include <vector>

namespace dealmpm
{
  /** What a G2P sweep updates on the particles. */
  enum class G2P
  {
    motion,      ///< velocity, position, displacement, reference location
    deformation, ///< L, F, then the after-deformation callback
    motion_and_deformation,
    /** position, displacement, reference location, L, F and the callback,
     * all from one nodal velocity; the particle velocity is the callback's
     * (Newmark) */
    position_and_deformation,
    /** motion that leaves the reference location at the step's start, for
     * the sweeps after it that compute their weights from it (MUSL with
     * Stencil::where_used) */
    motion_keeping_reference,
    /** deformation, then the reference location of the particle's
     * position (MUSL's stress update after motion_keeping_reference) */
    deformation_then_reference
  };

  /** What a G2P sweep @p what does. */
  template <G2P what>
  struct G2PParts
  {
    static constexpr bool motion = what == G2P::motion ||
                                   what == G2P::motion_and_deformation ||
                                   what == G2P::motion_keeping_reference;
    static constexpr bool move =
      motion || what == G2P::position_and_deformation;
    static constexpr bool deformation =
      !motion || what == G2P::motion_and_deformation;
    static constexpr bool keep_reference =
      what == G2P::motion_keeping_reference;
    static constexpr bool then_reference =
      what == G2P::deformation_then_reference;
  };

  /** A callback for sweeps without deformation. */
  struct NoAfterDeformation
  {
    template <typename... Args>
    void
    operator()(const Args &...) const
    {}
  };

  /** A gradient adjustment that leaves L as it is. */
  struct NoGradientAdjustment
  {
    template <typename... Args>
    void
    operator()(const Args &...) const
    {}
  };

  namespace g2p_sweep
  {
    template <int dim>
    struct BoxWeights;

    /** USL's light nodes (update_nodal_velocity()) lend L only the weight
     * w of their own increment and the particle's interpolated dv for the
     * rest: v_i - (1 - w) (dv_i - dv). A second pass over the stencil,
     * which is in cache, in the cells that have such nodes only
     * (@p cell is the particle's, in grid.cells), so that no other sweep
     * and few particles pay for it. */
    template <int dim, typename Weights, typename Particle, typename Arrays>
    DEAL_II_ALWAYS_INLINE inline void
    lend_light_nodes(const BackgroundGrid<dim> &grid,
                     const Weights             &weights,
                     const std::size_t          k,
                     const Particle            &p,
                     const GridCell<dim>       &cell,
                     const Arrays              &from,
                     const Tensor<1, dim>      &dv,
                     Tensor<2, dim>            &L)
    {
      if (from.weight && from.has_light_node(grid, cell))
        weights(k,
                p,
                cell,
                [&](const unsigned int n,
                    const double,
                    const Tensor<1, dim> &grad_N) DEAL_II_ALWAYS_INLINE {
                  const double light = 1. - from.weight[n];
                  if (light > 0)
                    for (unsigned int d = 0; d < dim; ++d)
                      for (unsigned int b = 0; b < dim; ++b)
                        L[d][b] +=
                          light * (dv[d] - from.increment[d][n]) * grad_N[b];
                });
    }

    /** Whether gather() sums by rows (gather_by_rows()). */
    template <int dim, typename Weights>
    constexpr bool by_rows = std::is_same_v<Weights, WindowWeights<dim>>;

    /** Adds a gather's vector sums over a node block (VelocityArrays::
     * block) into v_grid, dv and L: v in the first dim lanes of @p values,
     * dv in its next two (2D) or its fourth and @p rests (3D), L's column
     * b in @p column[b]. */
    template <bool motion, bool move, bool deformation, int dim>
    DEAL_II_ALWAYS_INLINE inline void
    add_lane_sums(const Lanes4 &values,
                  const Lanes2 &rests,
                  const Lanes4 (&column)[dim],
                  Tensor<1, dim> &v_grid,
                  Tensor<1, dim> &dv,
                  Tensor<2, dim> &L)
    {
      for (unsigned int d = 0; d < dim; ++d)
        {
          if (move)
            v_grid[d] += values[d];
          if constexpr (motion)
            {
              if constexpr (dim == 2)
                dv[d] += values[dim + d];
              else // dv_x in the fourth lane, dv_y and dv_z a pair
                dv[d] += d == 0 ? values[3] : rests[d - 1];
            }
          if (deformation)
            for (unsigned int b = 0; b < dim; ++b)
              L[d][b] += column[b][d];
        }
    }

    /** The rows' sums of gather_by_rows() from the velocity and its
     * increment interleaved by node (VelocityArrays::block): a node's
     * first four values (v, then dv, in 2D; v and dv_x in 3D) are one
     * load and one vector sum for the values and one for the slopes, 3D's
     * dv_y, dv_z a second pair. Each row's sums are scaled into vector
     * sums over the rows (the lanes of v and dv by v12; L's columns by
     * v12, s12 and s2), written into v_grid, dv and L once: as scalars a
     * row's scaling cost more than its nodes (47 instructions a 3D row).
     * Lanes past what a sweep reads hold the node's other numbers and are
     * not read. The same products and sums in the same order as
     * gather_by_rows() (v_grid, dv and L come in as zero). */
    template <bool motion,
              bool move,
              bool deformation,
              int  dim,
              typename Particle>
    DEAL_II_ALWAYS_INLINE inline void
    gather_rows_from_block(const WindowWeights<dim> &weights,
                           const std::size_t         k,
                           const Particle           &p,
                           const GridCell<dim>      &cell,
                           const double             *block,
                           Tensor<1, dim>           &v_grid,
                           Tensor<1, dim>           &dv,
                           Tensor<2, dim>           &L)
    {
      constexpr unsigned int stride = VelocityArrays<dim>::block_stride;
      static_assert(stride >= 5, "a node's block holds four values");
      constexpr bool second_pair = motion && dim == 3;
      // Over the rows: v12 times the values (v, dv), times the slopes
      // (L's first column), s12 and s2 times the values (its second and
      // third), v12 times 3D's dv_y, dv_z.
      Lanes4                  values = {}, column[dim] = {};
      [[maybe_unused]] Lanes2 rests = {};
      weights.rows(k,
                   p,
                   cell,
                   [&](const auto          n_x,
                       const unsigned int *row,
                       const NodeWindow   &w0,
                       const double        v12,
                       const double        s12,
                       const double        s2) DEAL_II_ALWAYS_INLINE {
                     Lanes4                  value = {}, slope = {};
                     [[maybe_unused]] Lanes2 rest = {}; // dv_y, dv_z (3D)
                     for (unsigned int k = 0; k < n_x; ++k)
                       {
                         const double *x = block + std::size_t(row[k]) * stride;
                         const Lanes4  first = load_lanes<Lanes4>(x);
                         value += w0.value[k] * first;
                         if (deformation)
                           slope += w0.slope[k] * first;
                         if constexpr (second_pair)
                           rest += w0.value[k] * load_lanes<Lanes2>(x + 4);
                       }
                     if (move || motion)
                       values += v12 * value;
                     if constexpr (second_pair)
                       rests += v12 * rest;
                     if (deformation)
                       {
                         column[0] += v12 * slope;
                         column[1] += s12 * value;
                         if constexpr (dim == 3)
                           column[2] += s2 * value;
                       }
                   });
      add_lane_sums<motion, move, deformation>(
        values, rests, column, v_grid, dv, L);
    }

    /** gather()'s v_grid, dv and L from stored weights (entries of
     * particle @p k in @p stencil) and the velocity and increment
     * interleaved by node (VelocityArrays::block), as vectors: a node's v
     * and dv (3D: v and dv_x; dv_y, dv_z a second pair) are one load, its
     * part of v_grid and dv one product and sum, of each of L's columns
     * one more. Lanes past what a sweep reads hold the node's other
     * numbers and are not read. The same products and sums in the same
     * order as node by node (v_grid, dv and L come in as zero): the 3D
     * CPDI column's G2P took about 46 instructions an entry that way. */
    template <bool motion, bool move, bool deformation, int dim>
    DEAL_II_ALWAYS_INLINE inline void
    gather_entries_from_block(const Stencil<dim> &stencil,
                              const std::size_t   k,
                              const double       *block,
                              Tensor<1, dim>     &v_grid,
                              Tensor<1, dim>     &dv,
                              Tensor<2, dim>     &L)
    {
      constexpr unsigned int stride = VelocityArrays<dim>::block_stride;
      static_assert(stride >= 5, "a node's block holds four values");
      constexpr bool          second_pair = motion && dim == 3;
      Lanes4                  values      = {};
      Lanes4                  column[dim] = {};
      [[maybe_unused]] Lanes2 rests       = {};
      for (unsigned int e = stencil.begin[k]; e < stencil.begin[k + 1]; ++e)
        {
          const double *x     = block + std::size_t(stencil.node[e]) * stride;
          const Lanes4  first = load_lanes<Lanes4>(x);
          const double  N     = stencil.N[e];
          if (move || motion)
            values += N * first;
          if constexpr (second_pair)
            rests += N * load_lanes<Lanes2>(x + 4);
          if (deformation)
            for (unsigned int b = 0; b < dim; ++b)
              column[b] += first * stencil.grad_N[e][b];
        }
      add_lane_sums<motion, move, deformation>(
        values, rests, column, v_grid, dv, L);
    }

    /** The velocity block (VelocityArrays::block) that stored weights
     * read as vectors (gather_entries_from_block()), or nullptr: other
     * weights, contact's body fields and light nodes read node by node. */
    template <int dim, typename Weights, typename Arrays>
    DEAL_II_ALWAYS_INLINE inline const double *
    stored_block(const Arrays &from)
    {
      if constexpr (std::is_same_v<Weights, StoredWeights<dim>> &&
                    std::is_same_v<Arrays, VelocityArrays<dim>>)
        return from.block;
      else
        return nullptr;
    }

    /** gather()'s v_grid, dv and L for windowed weights computed where
     * used, a row of nodes along x at a time (WindowWeights::rows()):
     * the row's sums with x's weights, then scaled by the other
     * directions'. */
    template <bool motion,
              bool move,
              bool deformation,
              int  dim,
              typename Particle,
              typename Arrays>
    DEAL_II_ALWAYS_INLINE inline void
    gather_by_rows(const WindowWeights<dim> &weights,
                   const std::size_t         k,
                   const Particle           &p,
                   const GridCell<dim>      &cell,
                   const Arrays             &from,
                   Tensor<1, dim>           &v_grid,
                   Tensor<1, dim>           &dv,
                   Tensor<2, dim>           &L)
    {
      if constexpr (std::is_same_v<Arrays, VelocityArrays<dim>>)
        if (from.block != nullptr)
          {
            gather_rows_from_block<motion, move, deformation>(
              weights, k, p, cell, from.block, v_grid, dv, L);
            return;
          }
      weights.rows(k,
                   p,
                   cell,
                   [&](const auto          n_x,
                       const unsigned int *row,
                       const NodeWindow   &w0,
                       const double        v12,
                       const double        s12,
                       const double        s2) DEAL_II_ALWAYS_INLINE {
                     double value[dim] = {}, slope[dim] = {},
                            increment[dim] = {};
                     for (unsigned int k = 0; k < n_x; ++k)
                       for (unsigned int d = 0; d < dim; ++d)
                         {
                           const double v = from.velocity[d][row[k]];
                           value[d] += w0.value[k] * v;
                           if (deformation)
                             slope[d] += w0.slope[k] * v;
                           if (motion)
                             increment[d] +=
                               w0.value[k] * from.increment[d][row[k]];
                         }
                     for (unsigned int d = 0; d < dim; ++d)
                       {
                         if (move)
                           v_grid[d] += v12 * value[d];
                         if (motion)
                           dv[d] += v12 * increment[d];
                         if (deformation)
                           {
                             L[d][0] += v12 * slope[d];
                             L[d][1] += s12 * value[d];
                             if constexpr (dim == 3)
                               L[d][2] += s2 * value[d];
                           }
                       }
                   });
    }

    /** The sums over particle @p k's stencil (in @p cell) that a
     * sweep needs, from the nodal arrays @p from: v_grid = sum N v (if it moves
     * the particle), dv = sum N dv and, with APIC (@p affine), B = sum N v (x)
     * (x_i - x_p) (if it updates the velocity), L = sum v (x) grad N (if it
     * deforms). In a box cell (BoxWeights, @p from a CellArrays) by
     * CellArrays::interpolate(), which needs no weights.
     */
    template <bool motion,
              bool move,
              bool deformation,
              int  dim,
              typename Weights,
              typename Particle,
              typename Arrays>
    DEAL_II_ALWAYS_INLINE inline void
    gather(const BackgroundGrid<dim> &grid,
           const Stencil<dim>        &stencil,
           const Weights             &weights,
           const std::size_t          k,
           const Particle            &p,
           const GridCell<dim>       &cell,
           const Arrays              &from,
           const bool                 affine,
           Tensor<1, dim>            &v_grid,
           Tensor<1, dim>            &dv,
           Tensor<2, dim>            &L,
           Tensor<2, dim>            &B)
    {
      if constexpr (std::is_same_v<Weights, BoxWeights<dim>>)
        {
          const Point<dim> &xi = p.get_reference_location();
          from.template interpolate<motion, move, deformation>(xi,
                                                               v_grid,
                                                               dv,
                                                               L);
          // APIC: B = L_v D (affine_transfer.h), before the light-node
          // pass below changes L.
          if (motion && affine)
            B = box_affine_moment(deformation ? L : from.velocity_gradient(xi),
                                  xi,
                                  cell.inverse_jacobian);
        }
      // APIC's B needs each node's weight: the per-node path below.
      else if (by_rows<dim, Weights> && !(motion && affine))
        {
          if constexpr (by_rows<dim, Weights>)
            gather_by_rows<motion, move, deformation>(
              weights, k, p, cell, from, v_grid, dv, L);
        }
      else if (const double *block = stored_block<dim, Weights>(from);
               block != nullptr && !(motion && affine))
        gather_entries_from_block<motion, move, deformation>(
          stencil, k, block, v_grid, dv, L);
      else
        {
          // APIC measures x_i - x_p from the stencil's positions (the
          // particle's own in the updated Lagrangian sweeps, which have not
          // moved it yet; its reference one in total Lagrangian), or, with
          // weights computed where used, from the particle's position.
          Point<dim> x_affine;
          if constexpr (computed_where_used<dim, Weights>)
            x_affine = p.get_location();
          else if (motion && affine)
            x_affine = stencil.position[k];
          weights(k,
                  p,
                  cell,
                  [&](const unsigned int    n,
                      const double          N,
                      const Tensor<1, dim> &grad_N) DEAL_II_ALWAYS_INLINE {
                    for (unsigned int d = 0; d < dim; ++d)
                      {
                        if (move)
                          v_grid[d] += N * from.velocity[d][n];
                        if (motion)
                          dv[d] += N * from.increment[d][n];
                        if (deformation)
                          for (unsigned int b = 0; b < dim; ++b)
                            L[d][b] += from.velocity[d][n] * grad_N[b];
                      }
                    if (motion && affine)
                      {
                        const Tensor<1, dim> r =
                          grid.node_positions[n] - x_affine;
                        for (unsigned int a = 0; a < dim; ++a)
                          for (unsigned int b = 0; b < dim; ++b)
                            B[a][b] += N * from.velocity[a][n] * r[b];
                      }
                  });
        }
      if constexpr (motion && deformation && Arrays::may_be_light)
        lend_light_nodes(grid, weights, k, p, cell, from, dv, L);
    }

    /** Writes and returns the particle's new velocity: with APIC, v = sum N v
     * and the B = sum N v (x) (x_i - x_p) P2G turns into C; else the FLIP/PIC
     * blend alpha (v_p + sum N dv) + (1 - alpha) sum N v. */
    template <int dim>
    DEAL_II_ALWAYS_INLINE inline Tensor<1, dim>
    update_velocity(const ArrayView<double> &props,
                    const CoreFields        &f,
                    const Tensor<1, dim>    &v_grid,
                    const Tensor<1, dim>    &dv,
                    const Tensor<2, dim>    &B,
                    const double             flip_fraction,
                    const bool               affine)
    {
      // FLIP and PIC without the blend's products: the same numbers but
      // for the sign of a zero (PIC 483 -> 470 instructions per
      // particle-step on the 2D column; FLIP's count did not move).
      Tensor<1, dim> v = v_grid; // APIC and PIC
      if (affine)
        write_tensor<dim>(&props[f.affine_velocity], B);
      else if (flip_fraction != 0.)
        {
          const Tensor<1, dim> v_old =
            read_vector<dim>(&props[FixedCore<dim>::velocity]);
          if (flip_fraction == 1.)
            v = v_old + dv;
          else
            v = flip_fraction * (v_old + dv) + (1. - flip_fraction) * v_grid;
        }
      write_vector<dim>(&props[FixedCore<dim>::velocity], v);
      return v;
    }

    /** Moves the particle from @p x_p by @p dx: displacement and position
     * only (total Lagrangian: the particle keeps its reference cell). */
    template <int dim, typename Particle>
    DEAL_II_ALWAYS_INLINE inline Point<dim>
    displace(Particle                &p,
             const ArrayView<double> &props,
             const Point<dim>        &x_p,
             const Tensor<1, dim>    &dx)
    {
      write_vector<dim>(&props[FixedCore<dim>::displacement],
                        read_vector<dim>(&props[FixedCore<dim>::displacement]) +
                          dx);
      const Point<dim> x = x_p + dx;
      p.set_location(x);
      return x;
    }

    /** Moves the particle from @p x_p by @p dx: displacement, position and
     * reference location in its old cell @p c; sets @p left_cell if that
     * location is outside the cell by more than round-off. Returns whether
     * it is outside at all (plan_relocation() then looks at it). @p box: @p c
     * is an axis-aligned box (GridCell::reference_point_in_box()). */
    template <bool set_reference = true,
              bool box           = false,
              int  dim,
              typename Particle>
    DEAL_II_ALWAYS_INLINE inline bool
    move(Particle                &p,
         const ArrayView<double> &props,
         const GridCell<dim>     &c,
         const Point<dim>        &x_p,
         const Tensor<1, dim>    &dx,
         bool                    &left_cell)
    {
      const Point<dim> x = displace(p, props, x_p, dx);
      const Point<dim> xi =
        box ? c.reference_point_in_box(x) : c.reference_point(x);
      if (set_reference)
        p.set_reference_location(xi);
      // The extreme coordinates first: two comparisons instead of 2 dim.
      double lowest = xi[0], highest = xi[0];
      for (unsigned int d = 1; d < dim; ++d)
        {
          lowest  = std::min(lowest, xi[d]);
          highest = std::max(highest, xi[d]);
        }
      const bool outside = (lowest < 0.) | (highest > 1.);
      // Slack so that a particle sitting on a face does not trigger a sort.
      const double tolerance = 1e-12;
      if (outside)
        for (unsigned int d = 0; d < dim; ++d)
          left_cell = left_cell || xi[d] < -tolerance || xi[d] > 1. + tolerance;
      return outside;
    }

    /** A particle at @p k in the step's order that left the box
     * grid.cells[@p i] by more than round-off along each axis it left
     * by, each such face with a cell behind it (so no wall holds it): if
     * the owned cell on that side holds it, it is put there here, where
     * its data are at hand (its reference location set, a Move in
     * @p moves), and true; else false, and plan_relocation() looks at it.
     * It left by more than round-off, so the ranks relocate for sure and
     * nothing needs undoing (cancel_relocation()). The cell is the one
     * plan_relocation() tries first, found by the same steps
     * (side_neighbors.h), so the answers are the same. */
    template <int dim, typename Particle, typename Move>
    inline bool
    enter_side_neighbor(const BackgroundGrid<dim> &grid,
                        const std::size_t          k,
                        const unsigned int         i,
                        Particle                  &p,
                        std::vector<Move>         &moves)
    {
      if (!grid.has_side_neighbors())
        return false;
      const unsigned int side =
        side_neighbors::clean_exit_side(grid, i, p.get_reference_location());
      if (side == numbers::invalid_unsigned_int)
        return false; // relocation or the walls decide
      const GridCell<dim> *const to = side_neighbors::owned_at(grid, i, side);
      if (to == nullptr)
        return false; // none, or a ghost's: another rank's
      // The next cell's leavers mostly go the same way: ask the cache now
      // for the cell they would enter (G2P of the flowing column stalled
      // on reading it, to->affine below).
      if (i + 1 < grid.cells.size())
        side_neighbors::prefetch_cell(grid.side_neighbor(i + 1, side));
      const Point<dim> xi_new = to->reference_point(p.get_location());
      if (!GeometryInfo<dim>::is_inside_unit_cell(xi_new))
        return false;
      p.set_reference_location(xi_new);
      moves.push_back({static_cast<unsigned int>(k),
                       i,
                       static_cast<unsigned int>(to - grid.cells.data()),
                       true,
                       xi_new});
      return true;
    }

    /** move(), and the particle's position @p k in the step's order and
     * its old cell in @p leavers if it is outside that cell (or, where
     * enter_side_neighbor() put it into a neighbour, its Move). */
    template <bool set_reference,
              bool box,
              int  dim,
              typename Particle,
              typename Leavers>
    DEAL_II_ALWAYS_INLINE inline void
    move_and_record(const BackgroundGrid<dim> &grid,
                    const std::size_t          k,
                    Particle                  &p,
                    const ArrayView<double>   &props,
                    const GridCell<dim>       &c,
                    const Point<dim>          &x_p,
                    const Tensor<1, dim>      &dx,
                    Leavers                   &leavers,
                    bool                      &left_cell)
    {
      if (move<set_reference, box>(p, props, c, x_p, dx, left_cell))
        {
          const unsigned int i = index_in_grid(grid, c);
          if constexpr (set_reference && box)
            if (enter_side_neighbor(grid, k, i, p, leavers.moves))
              return;
          leavers.position.push_back(k);
          leavers.cell.push_back(i);
        }
    }

    /** F <- dF F with dF = @p increment(dt L) (I + dt L unless the scene
     * chose another DeformationUpdate); returns the new F. */
    template <int dim, typename Increment>
    DEAL_II_ALWAYS_INLINE inline Tensor<2, dim>
    deform(const ArrayView<double> &props,
           const Tensor<2, dim>    &L,
           const double             dt,
           const Increment         &increment)
    {
      const Tensor<2, dim> F =
        increment(dt * L) *
        read_tensor<dim>(&props[FixedCore<dim>::deformation_gradient]);
      write_tensor<dim>(&props[FixedCore<dim>::deformation_gradient], F);
      return F;
    }

    /** The deformation part of a sweep for particle @p p in @p c:
     * @p adjust_gradient(c, props, L), with @p reference (total Lagrangian)
     * L = (dF/dt) F^-1, F updated (deform()), then @p after_deformation(p,
     * props, L, F, h) with the cell size h (scaled by F's smallest stretch
     * with @p reference). */
    template <bool reference,
              int  dim,
              typename Particle,
              typename AdjustGradient,
              typename Increment,
              typename AfterDeformation>
    DEAL_II_ALWAYS_INLINE inline void
    deform_and_report(Particle                &p,
                      const ArrayView<double> &props,
                      const GridCell<dim>     &c,
                      Tensor<2, dim>           L,
                      const double             dt,
                      const AdjustGradient    &adjust_gradient,
                      const Increment         &f_increment,
                      AfterDeformation        &after_deformation)
    {
      adjust_gradient(c, props, L);
      if constexpr (reference)
        L = L * invert(read_tensor<dim>(
                  &props[FixedCore<dim>::deformation_gradient]));
      const Tensor<2, dim> F = deform(props, L, dt, f_increment);
      after_deformation(
        p, props, L, F, reference ? c.h * smallest_stretch(F) : c.h);
    }

    /** One box cell's nodal velocities and increments (and USL's
     * light-node weights) copied into locals, indexed by the cell's vertex
     * (what the light-node pass reads through BoxWeights), and prepared for
     * interpolation (BoxQ1Component): the nodal arrays are read once a
     * cell instead of once a particle. */
    template <int dim, bool light>
    struct CellArrays
    {
      static constexpr bool         may_be_light = light;
      static constexpr unsigned int n_vertices   = GridCell<dim>::n_vertices;
      double                        velocity[dim][n_vertices];
      double                        increment[dim][n_vertices];
      double                        light_weight[n_vertices];
      /** light_weight, or nullptr when there are no light nodes (as
       * VelocityArrays' weight). Not copyable: weight points into this
       * object. */
      const double *weight     = nullptr;
      bool          light_cell = false;

      /** The same by component, for interpolate(). */
      BoxQ1Component<dim> velocity_q1[dim], increment_q1[dim];

      CellArrays(const CellArrays &) = delete;

      DEAL_II_ALWAYS_INLINE
      CellArrays(const VelocityArrays<dim, light> &from,
                 const GridCell<dim>              &cell,
                 const unsigned int               *nodes)
      {
        for (unsigned int v = 0; v < n_vertices; ++v)
          for (unsigned int d = 0; d < dim; ++d)
            {
              velocity[d][v]  = from.velocity[d][nodes[v]];
              increment[d][v] = from.increment[d][nodes[v]];
            }
        for (unsigned int d = 0; d < dim; ++d)
          {
            velocity_q1[d].set(velocity[d], cell.inverse_jacobian);
            increment_q1[d].set(increment[d], cell.inverse_jacobian);
          }
        if (light && from.weight)
          {
            weight = light_weight;
            for (unsigned int v = 0; v < n_vertices; ++v)
              {
                light_weight[v] = from.weight[nodes[v]];
                light_cell      = light_cell || light_weight[v] < 1;
              }
          }
      }

      /** Whether a node of this cell weighs less than 1 (asked only when
       * weight is set). */
      DEAL_II_ALWAYS_INLINE bool
      has_light_node(const BackgroundGrid<dim> &, const GridCell<dim> &) const
      {
        return light_cell;
      }

      /** The real gradient of the velocity at unit-cell point @p xi
       * (APIC's B in a sweep that does not deform). */
      DEAL_II_ALWAYS_INLINE Tensor<2, dim>
                            velocity_gradient(const Point<dim> &xi) const
      {
        Tensor<2, dim> L;
        for (unsigned int d = 0; d < dim; ++d)
          {
            double grad[dim];
            velocity_q1[d].value_and_gradient(xi, grad);
            for (unsigned int b = 0; b < dim; ++b)
              L[d][b] = grad[b];
          }
        return L;
      }

      /** gather()'s sums at unit-cell point @p xi but APIC's B. */
      template <bool motion, bool move, bool deformation>
      DEAL_II_ALWAYS_INLINE void
      interpolate(const Point<dim> &xi,
                  Tensor<1, dim>   &v_grid,
                  Tensor<1, dim>   &dv,
                  Tensor<2, dim>   &L) const
      {
        for (unsigned int d = 0; d < dim; ++d)
          {
            double grad[dim];
            if (deformation)
              {
                const double v = velocity_q1[d].value_and_gradient(xi, grad);
                for (unsigned int b = 0; b < dim; ++b)
                  L[d][b] = grad[b];
                if (move)
                  v_grid[d] = v;
              }
            else if (move)
              v_grid[d] = velocity_q1[d].value(xi);
            if (motion)
              dv[d] = increment_q1[d].value(xi);
          }
      }
    };

    /** LinearWeights in an axis-aligned box cell without hanging nodes
     * (the same numbers), handing out the vertex instead of the node: the
     * index into CellArrays. */
    template <int dim>
    struct BoxWeights
    {
      template <typename Particle, typename Function>
      DEAL_II_ALWAYS_INLINE void
      operator()(const std::size_t,
                 const Particle      &p,
                 const GridCell<dim> &c,
                 Function           &&f) const
      {
        LinearWeights<dim>::at_in_box(p.get_reference_location(), c, f);
      }
    };

    /** Visit the particles with @p per_particle(k, particle, cell,
     * weights, arrays, sums), sums a local @p remap's Sums (the box cell's,
     * handed to @p remap.end_box_cell(cell, nodes, sums) after its
     * particles: a local the compiler keeps in registers, which it cannot
     * do with a member that the particles' properties might alias): a cell
     * at a time with CellArrays and BoxWeights where the weights are linear
     * ones computed here (LinearWeights), the particles read one set of nodal
     * arrays (VelocityArrays, not one per body) and the cell is a box without
     * hanging nodes; else each particle with @p weights and @p arrays. Both
     * give the same numbers in the same order. The cell path passes k = 0 and
     * vertex indices: fine for what reads weights computed here (APIC's
     * sums there have closed forms, affine_transfer.h). */
    template <int dim,
              typename Weights,
              typename Arrays,
              typename Remap,
              typename PerParticle>
    DEAL_II_ALWAYS_INLINE inline void
    visit(const BackgroundGrid<dim> &grid,
          ParticleSet<dim>          &particles,
          const Weights             &weights,
          const Arrays              &arrays,
          Remap                     &remap,
          const PerParticle         &per_particle)
    {
      // The re-map reads the windows the gather computed.
      if constexpr (!std::is_same_v<Remap, NoRemap> &&
                    std::is_same_v<Weights, WindowWeights<dim>>)
        weights.keep_windows = true;
      using Sums = typename Remap::Sums;
      Sums           no_sums; // where the weights are not BoxWeights
      constexpr bool by_cell =
        std::is_same_v<Weights, LinearWeights<dim>> &&
        (std::is_same_v<Arrays, VelocityArrays<dim, false>> ||
         std::is_same_v<Arrays, VelocityArrays<dim, true>>);
      if constexpr (by_cell)
        {
          // k: the particle's position in the step's order (these weights
          // do not need it; the record of particles that left does).
          std::size_t                                  k = 0;
          const ParticlesByCell<dim, ParticleSet<dim>> by_cell(grid, particles);
          for (std::size_t i = 0; i < grid.cells.size(); ++i)
            {
              // Cells without particles (the air above a body) would set
              // up their CellArrays for nothing.
              if (by_cell.empty(i))
                continue;
              const GridCell<dim> &c = grid.cells[i];
              if (c.first_weight == numbers::invalid_unsigned_int &&
                  LinearWeights<dim>::is_box(c))
                {
                  const unsigned int *const nodes =
                    &grid.cell_nodes[c.first_node];
                  const CellArrays<dim, Arrays::may_be_light> local(arrays,
                                                                    c,
                                                                    nodes);
                  Sums                                        sums;
                  by_cell.for_each(i, [&](auto &p) DEAL_II_ALWAYS_INLINE {
                    per_particle(k++, p, c, BoxWeights<dim>(), local, sums);
                  });
                  remap.end_box_cell(c, nodes, sums);
                }
              else
                by_cell.for_each(i, [&](auto &p) DEAL_II_ALWAYS_INLINE {
                  per_particle(k++, p, c, weights, arrays, no_sums);
                });
            }
        }
      else
        for_each_particle_in_stencil_order(
          grid,
          particles,
          [&](const std::size_t k, auto &p, const GridCell<dim> &c)
            DEAL_II_ALWAYS_INLINE {
              per_particle(
                k, p, c, weights, arrays.of(p.get_properties()), no_sums);
            });
    }
  } // namespace g2p_sweep

  namespace g2p_sweep
  {
    /** grid_to_particle() with APIC's B (@p affine) or without. */
    template <G2P         what,
              Formulation formulation,
              bool        affine,
              int         dim,
              typename Arrays,
              typename AfterDeformation,
              typename AdjustGradient,
              typename Increment,
              typename Remap>
    bool
    sweep(const BackgroundGrid<dim> &grid,
          const Stencil<dim>        &stencil,
          const Arrays              &arrays,
          const double               dt,
          const double               flip_fraction,
          ParticleSet<dim>          &particles,
          AfterDeformation          &after_deformation,
          const AdjustGradient      &adjust_gradient,
          const Increment           &f_increment,
          Remap                     &remap)
    {
      using parts              = G2PParts<what>;
      constexpr bool reference = formulation == Formulation::total_lagrangian;
      const CoreFields &f      = particles.fields;
      bool              left_cell = false;
      auto             &leavers =
        particles.leavers; // who leaves a cell, for plan_relocation()
      if constexpr (parts::move && !reference)
        leavers.start();
      with_weights(grid, stencil, [&](const auto &weights) {
        g2p_sweep::visit(
          grid,
          particles,
          weights,
          arrays,
          remap,
          [&](const std::size_t    k,
              auto                &p,
              const GridCell<dim> &c,
              const auto          &weights_here,
              const auto          &from,
              auto                &sums) DEAL_II_ALWAYS_INLINE {
            constexpr bool box =
              std::is_same_v<std::decay_t<decltype(weights_here)>,
                             g2p_sweep::BoxWeights<dim>>;
            Tensor<1, dim>          v_grid, dv;
            Tensor<2, dim>          L, B;
            const Point<dim>        x_p   = p.get_location();
            const ArrayView<double> props = p.get_properties();
            g2p_sweep::gather<parts::motion, parts::move, parts::deformation>(
              grid,
              stencil,
              weights_here,
              k,
              p,
              c,
              from,
              affine,
              v_grid,
              dv,
              L,
              B);
            if (parts::motion)
              {
                const Tensor<1, dim> v = g2p_sweep::update_velocity(
                  props, f, v_grid, dv, B, flip_fraction, affine);
                remap.add(weights_here, k, p, c, v, B, sums);
              }
            if constexpr (parts::move && reference)
              g2p_sweep::displace(p, props, x_p, dt * v_grid);
            else if constexpr (parts::move)
              g2p_sweep::move_and_record<!parts::keep_reference, box>(
                grid, k, p, props, c, x_p, dt * v_grid, leavers, left_cell);
            if (parts::deformation)
              g2p_sweep::deform_and_report<reference>(p,
                                                      props,
                                                      c,
                                                      L,
                                                      dt,
                                                      adjust_gradient,
                                                      f_increment,
                                                      after_deformation);
            if constexpr (parts::then_reference && box)
              p.set_reference_location(c.reference_point_in_box(x_p));
            else if constexpr (parts::then_reference)
              p.set_reference_location(c.reference_point(x_p));
          });
      });
      return left_cell;
    }
  } // namespace g2p_sweep

  /**
   * G2P from the nodal velocity field (fields.velocity) and its increment
   * (fields.velocity_increment, for FLIP); @p fields is a NodalFields, or
   * BodyVelocities for each particle to read its own body's fields:
   * - motion: particle velocity alpha (v_p + sum N dv) + (1 - alpha) sum N v
   *   (alpha = FLIP fraction), position and displacement += dt sum N v, and
   *   the reference location in the old cell; with APIC (the particles carry
   *   an affine velocity) v_p = sum N v and B_p = sum N v (x) (x_i - x_p)
   *   is stored; P2G turns it into C_p = B_p D_p^-1 at the particle's next
   *   position (Jiang et al. 2015): this, not C_p = sum v (x) grad N, makes
   *   the grid -> particle -> grid round trip conserve angular momentum for
   *   any shape functions, multilinear ones included;
   * - deformation: L = sum v (x) grad N, then @p adjust_gradient(cell,
   *   properties, L) (MixedCellSplit), F <- @p f_increment(dt L) F
   *   (DeformationUpdate; I + dt L by default), then
   *   @p after_deformation(particle, properties, L, F, h) (the stress
   *   update, see StressUpdate; h the particle's cell size for the stable
   *   step) in the same sweep: the step is bound by memory traffic, and a
   *   sweep less is worth more than arithmetic saved.
   *
   * With @p formulation total Lagrangian the stencil holds the reference
   * gradients Grad N (compute_reference_stencil()): sum v (x) Grad N is
   * dF/dt, so L = dF/dt F_n^-1 (and F_n+1 = F_n + dt dF/dt to round-off
   * with the first-order increment); the particle keeps its reference
   * cell, and the cell size h is scaled by F's smallest stretch. APIC's
   * x_i - x_p are reference positions then, as the stencil's positions
   * are.
   *
   * - position_and_deformation: motion without the velocity update, and
   *   deformation, from the same nodal velocity (Newmark's re-mapped
   *   displacement velocity, newmark_predict()).
   *
   * With @p remap a RemapInSweep (MUSL's motion), the sweep also re-maps
   * the particles' mass and updated momentum to the grid.
   *
   * @return true if motion moved some local particle out of its cell
   * (never with total Lagrangian).
   */
  template <G2P         what,
            Formulation formulation = Formulation::updated_lagrangian,
            int         dim,
            typename Fields,
            typename AfterDeformation = NoAfterDeformation,
            typename AdjustGradient   = NoGradientAdjustment,
            typename Increment        = FirstOrderIncrement,
            typename Remap            = NoRemap>
  bool
  grid_to_particle(const BackgroundGrid<dim> &grid,
                   const Stencil<dim>        &stencil,
                   const Fields              &fields,
                   const double               dt,
                   const double               flip_fraction,
                   ParticleSet<dim>          &particles,
                   AfterDeformation         &&after_deformation = {},
                   const AdjustGradient      &adjust_gradient   = {},
                   const Increment           &f_increment       = {},
                   Remap                    &&remap             = {})
  {
    // APIC's B compiled only into the sweeps that update the velocity,
    // and run only where the particles carry it (a run-time switch cost
    // the 3D column's USL sweep 20 instructions per particle-step).
    const auto sweep = [&](const auto affine) {
      const auto run = [&](const auto &arrays) {
        return g2p_sweep::sweep<what, formulation, decltype(affine)::value>(
          grid,
          stencil,
          arrays,
          dt,
          flip_fraction,
          particles,
          after_deformation,
          adjust_gradient,
          f_increment,
          remap);
      };
      // Windowed weights read the nodes interleaved (APIC's motion takes
      // the per-node path, which reads the vectors).
      constexpr bool motion = G2PParts<what>::motion;
      if constexpr (std::is_same_v<Fields, NodalFields<dim>> &&
                    !(motion && decltype(affine)::value))
        if (stencil.on_windows() || !stencil.where_used)
          return run(
            fill_velocity_block(fields, velocity_arrays(fields), motion));
      return run(velocity_arrays(fields));
    };
    if constexpr (G2PParts<what>::motion)
      if (particles.fields.affine_velocity != numbers::invalid_unsigned_int)
        return sweep(std::true_type());
    return sweep(std::false_type());
  }
} // namespace dealmpm
