#pragma once

#include <dealmpm/materials/j2_plasticity.h>

namespace dealmpm
{
  /** Johnson and Cook's (1983) flow stress and heating constants. */
  struct JohnsonCookParameters
  {
    double A = 90e6, B = 292e6, n = 0.31; ///< (A + B alpha^n)
    double C                   = 0.025;   ///< (1 + C ln(rate / reference))
    double reference_rate      = 1;       ///< 1/s
    double m                   = 1.09;    ///< (1 - T*^m)
    double room_temperature    = 298;     ///< K
    double melting_temperature = 1356;    ///< K
    double specific_heat       = 383;     ///< J/(kg K)
    double taylor_quinney      = 0.9;     ///< fraction of plastic work to heat
  };

  /**
   * J2 plasticity (the same finite-strain radial return) with Johnson and
   * Cook's flow stress
   * sigma_y = (A + B alpha^n)(1 + C ln(max(rate / rate_0, 1)))(1 - T*^m),
   * rate = d_gamma / dt the equivalent plastic strain rate of the step,
   * T* = (T - T_room) / (T_melt - T_room) in [0, 1]. The return solves for
   * d_gamma with the rate term in it (a scalar Newton solve, bracketed);
   * the temperature, an internal variable, rises adiabatically after each
   * return by taylor_quinney sigma_y d_gamma / (rho0 c_p), so that within
   * a step it is the temperature at its start. Defaults: OFHC copper
   * (Johnson and Cook 1983).
   */
  template <int dim>
  class JohnsonCook : public J2Plasticity<dim>
  {
  public:
    JohnsonCook(const LameParameters &lame, const JohnsonCookParameters &jc);

    void
    initialize_internal_variables(ArrayView<double> internal) const override;

    /** The temperature of a state. */
    double
    temperature(ArrayView<const double> internal) const
    {
      return internal[this->model_index];
    }

  protected:
    std::vector<FieldDescription>
    model_variables() const override
    {
      return {{"temperature", 1}};
    }

    std::array<double, 2>
    flow_stress(const double            alpha,
                const double            d_gamma,
                const double            dt,
                ArrayView<const double> internal) const override;

    void
    after_plastic_step(const double      d_gamma,
                       const double      flow,
                       ArrayView<double> internal) const override;

  private:
    JohnsonCookParameters jc;
  };
} // namespace dealmpm
