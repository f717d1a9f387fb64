#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <dealmpm/base/load_curve.h>

#include <set>

namespace dealmpm
{
  using namespace dealii;

  /**
   * A base motion (section 'Base shaking'): the record and the ground
   * beyond the base. The grid's base (effects/base_shaking.h) and an FEM
   * region's 'Shaken boundaries' (fem/solid_region.h) move with it.
   */
  template <int dim>
  struct BaseMotion
  {
    /** The grid's base ids (an FEM region names its own). */
    std::set<types::boundary_id> ids;
    /** Rigid: the base nodes move with the record. Compliant: dashpots
     * with the incoming wave (the ground beyond the base, as
     * 'absorbing boundary', lets waves leave). */
    bool rigid = true;
    /** The record is an acceleration (integrated exactly) or a velocity. */
    bool           acceleration = true;
    Tensor<1, dim> amplitude;
    LoadCurve      record;
    /** The ground beyond a compliant base. */
    double density = 0, p_wave_speed = 0, s_wave_speed = 0;

    /** The record's velocity at @p t: amplitude times the record (or its
     * integral from 0). A compliant base's record is the outcrop motion,
     * twice the incoming wave's. */
    Tensor<1, dim>
    velocity(const double t) const
    {
      return amplitude * (acceleration ? record.integral(t) : record(t));
    }

    /**
     * The velocity of a base node of mass @p m whose velocity without the
     * base would be @p v, the record's being @p w: w (rigid) or, compliant,
     * backward Euler on m dv/dt = rho c |A| (w - v) per direction (c_p
     * along the node's outward area vector @p area, c_s across it),
     * v_n <- (v_n + a_p w_n) / (1 + a_p), a_p = dt rho c_p |A| / m: stable
     * however light the node.
     */
    Tensor<1, dim>
    base_velocity(const Tensor<1, dim> &area,
                  const double          m,
                  const Tensor<1, dim> &v,
                  const Tensor<1, dim> &w,
                  const double          dt) const
    {
      if (rigid)
        return w;
      const double         A    = area.norm();
      const Tensor<1, dim> n    = area / A;
      const double         load = dt * density * A / m;
      const double         a_p = load * p_wave_speed, a_s = load * s_wave_speed;
      const Tensor<1, dim> v_n = (v * n) * n, w_n = (w * n) * n;
      return (v_n + a_p * w_n) / (1 + a_p) +
             (v - v_n + a_s * (w - w_n)) / (1 + a_s);
    }
  };
} // namespace dealmpm
