#include <deal.II/base/point.h>

#include <dealmpm/materials/initial_stress.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <vector>

namespace dealmpm
{
  template <int dim>
  SymmetricTensor<2, dim>
  geostatic_stress(const double          sigma_v,
                   const Tensor<1, dim> &n,
                   const double          K0)
  {
    const SymmetricTensor<2, dim> vertical = symmetrize(outer_product(n, n));
    return sigma_v *
           (vertical + K0 * (unit_symmetric_tensor<dim>() - vertical));
  }

  namespace
  {
    /** One step of @p material from its initial state to the stretch
     * exp(sum e_a q_a (x) q_a); its stress and state. */
    template <int dim>
    struct Step
    {
      const Material<dim>            &material;
      std::array<Tensor<1, dim>, dim> axes;
      std::vector<double>             initial;
      Tensor<2, dim>                  F;
      SymmetricTensor<2, dim>         stress;
      std::vector<double>             internal;

      Step(const Material<dim> &material, const unsigned int n_internal)
        : material(material)
        , initial(n_internal)
      {
        material.initialize_internal_variables(make_array_view(initial));
      }

      void
      run(const std::array<double, dim> &log_stretch)
      {
        Tensor<2, dim> L;
        F = 0;
        for (unsigned int a = 0; a < dim; ++a)
          {
            const Tensor<2, dim> axis = outer_product(axes[a], axes[a]);
            L += log_stretch[a] * axis;
            F += std::exp(log_stretch[a]) * axis;
          }
        stress   = 0;
        internal = initial;
        material.update_stress(L, F, 1., stress, make_array_view(internal));
      }

      /** The stress along the axes less @p target's. */
      std::array<double, dim>
      residual(const std::array<double, dim> &target) const
      {
        std::array<double, dim> r;
        for (unsigned int a = 0; a < dim; ++a)
          r[a] = axes[a] * (stress * axes[a]) - target[a];
        return r;
      }
    };

    template <int dim>
    double
    norm(const std::array<double, dim> &r)
    {
      double sum = 0;
      for (const double value : r)
        sum += value * value;
      return std::sqrt(sum);
    }

    /** One Newton step of start_at_stress() on the principal
     * log-stretches @p e whose residual is @p r (both updated, and @p step
     * run at the new @p e); false when the residual is not finite. */
    template <int dim>
    bool
    newton_step(Step<dim>                     &step,
                const std::array<double, dim> &principal,
                std::array<double, dim>       &e,
                std::array<double, dim>       &r)
    {
      // The Jacobian by differences, on the compressed side: from zero
      // stress, a stretch is tension, which a cohesionless soil or a
      // fluid with its tension cut-off answer with no stress at all. The
      // models are smooth in their elastic range, and the residual itself
      // is exact.
      Eigen::Matrix<double, dim, dim> jacobian;
      const double                    h = -1e-7;
      for (unsigned int b = 0; b < dim; ++b)
        {
          std::array<double, dim> shifted = e;
          shifted[b] += h;
          step.run(shifted);
          const std::array<double, dim> r_b = step.residual(principal);
          for (unsigned int a = 0; a < dim; ++a)
            jacobian(a, b) = (r_b[a] - r[a]) / h;
        }
      Eigen::Matrix<double, dim, 1> rhs;
      for (unsigned int a = 0; a < dim; ++a)
        rhs(a) = -r[a];
      const Eigen::Matrix<double, dim, 1> de =
        jacobian.completeOrthogonalDecomposition().solve(rhs);
      // Backtracking: a model whose stiffness grows with the pressure
      // (Modified Cam-Clay from its reference pressure) makes the full
      // step overshoot by orders of magnitude.
      const double            before   = norm<dim>(r);
      double                  fraction = 1;
      std::array<double, dim> tried    = e;
      for (unsigned int halving = 0; halving < 40; ++halving, fraction /= 2)
        {
          for (unsigned int a = 0; a < dim; ++a)
            tried[a] = e[a] + fraction * de(a);
          step.run(tried);
          r = step.residual(principal);
          if (norm<dim>(r) < before) // false for NaN
            break;
        }
      e = tried;
      return std::isfinite(norm<dim>(r));
    }

    /**
     * Move the start @p e (residual @p r) of start_at_stress() to the
     * isotropic compression whose mean stress is the target's, when that
     * is closer. A model whose stiffness grows with the pressure
     * (Modified Cam-Clay from a low reference pressure) has almost none
     * unstrained: Newton's first step from there overshoots by orders of
     * magnitude, and in 3D the backtracking shrank it to nothing. Along
     * the isotropic line the mean stress falls monotonically with the
     * strain: bisection, on a bracket grown until it holds the target (to
     * a log strain of -2).
     */
    template <int dim>
    void
    isotropic_start(Step<dim>                     &step,
                    const std::array<double, dim> &principal,
                    std::array<double, dim>       &e,
                    std::array<double, dim>       &r)
    {
      double target = 0;
      for (const double value : principal)
        target += value / dim;
      const auto mean_at = [&](const double strain) {
        std::array<double, dim> isotropic;
        isotropic.fill(strain);
        step.run(isotropic);
        double mean = 0;
        for (unsigned int a = 0; a < dim; ++a)
          mean += step.axes[a] * (step.stress * step.axes[a]) / dim;
        return mean;
      };
      double low = -0.01, high = 0;
      // Whether the bracket [low, high] holds the target.
      bool holds = target < 0 && mean_at(low) <= target;
      while (target < 0 && !holds && low > -2)
        {
          high = low;
          low *= 2;
          holds = mean_at(low) <= target;
        }
      if (holds)
        {
          for (unsigned int i = 0; i < 60; ++i)
            {
              const double middle                      = (low + high) / 2;
              (mean_at(middle) <= target ? low : high) = middle;
            }
          std::array<double, dim> start;
          start.fill(low);
          step.run(start);
          const std::array<double, dim> r_start = step.residual(principal);
          if (norm<dim>(r_start) < norm<dim>(r))
            {
              e = start;
              r = r_start;
            }
        }
      step.run(e);
    }
  } // namespace

  template <int dim>
  double
  confined_stress_ratio(const Material<dim>  &material,
                        const unsigned int    n_internal,
                        const Tensor<1, dim> &n)
  {
    Step<dim> step(material, n_internal);
    step.axes[0] = n / n.norm();
    if constexpr (dim == 2)
      step.axes[1] = Tensor<1, 2>({-step.axes[0][1], step.axes[0][0]});
    else
      {
        // Any two unit vectors normal to n and to each other.
        const unsigned int least =
          std::abs(n[0]) <= std::abs(n[1]) ?
            (std::abs(n[0]) <= std::abs(n[2]) ? 0 : 2) :
            (std::abs(n[1]) <= std::abs(n[2]) ? 1 : 2);
        step.axes[1] =
          cross_product_3d(step.axes[0], Point<3>::unit_vector(least));
        step.axes[1] /= step.axes[1].norm();
        step.axes[2] = cross_product_3d(step.axes[0], step.axes[1]);
      }
    // The ratio of the changes: a model whose unstrained state carries a
    // stress (Modified Cam-Clay's reference pressure) has its own.
    std::array<double, dim> e{};
    step.run(e);
    const SymmetricTensor<2, dim> unstrained = step.stress;
    e[0]                                     = -1e-6;
    step.run(e);
    const SymmetricTensor<2, dim> change = step.stress - unstrained;
    return (step.axes[1] * (change * step.axes[1])) /
           (step.axes[0] * (change * step.axes[0]));
  }

  template <int dim>
  bool
  start_at_stress(const Material<dim>           &material,
                  const SymmetricTensor<2, dim> &target,
                  Tensor<2, dim>                &F,
                  SymmetricTensor<2, dim>       &stress,
                  ArrayView<double>              internal)
  {
    Step<dim> step(material, internal.size());
    // Eigen's solver: it keeps the axes orthonormal when principal
    // stresses repeat (K0 = 1, or the two horizontal ones in 3D).
    Eigen::Matrix<double, dim, dim> matrix;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        matrix(i, j) = target[i][j];
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, dim, dim>> eigen(
      matrix);
    std::array<double, dim> principal;
    for (unsigned int a = 0; a < dim; ++a)
      {
        principal[a] = eigen.eigenvalues()(a);
        for (unsigned int i = 0; i < dim; ++i)
          step.axes[a][i] = eigen.eigenvectors()(i, a);
      }
    const double scale     = std::max(target.norm(), 1e-300);
    const double tolerance = 1e-9 * scale;

    std::array<double, dim> e{};
    step.run(e);
    std::array<double, dim> r = step.residual(principal);
    if (norm<dim>(r) > tolerance)
      isotropic_start<dim>(step, principal, e, r);
    for (unsigned int iteration = 0; iteration < 50 && norm<dim>(r) > tolerance;
         ++iteration)
      {
        if (!newton_step<dim>(step, principal, e, r))
          return false;
      }
    // Off the axes the models are isotropic: nothing to check but the
    // whole tensor.
    if (!((step.stress - target).norm() <= tolerance))
      return false;
    F      = step.F;
    stress = step.stress;
    for (unsigned int i = 0; i < internal.size(); ++i)
      internal[i] = step.internal[i];
    return true;
  }

#define DEALMPM_INSTANTIATE(dim)                                                    \
  template SymmetricTensor<2, dim> geostatic_stress(double,                         \
                                                    const Tensor<1, dim> &,         \
                                                    double);                        \
  template double                  confined_stress_ratio(const Material<dim> &,     \
                                                         unsigned int,              \
                                                         const Tensor<1, dim> &);   \
  template bool                    start_at_stress(const Material<dim> &,           \
                                                   const SymmetricTensor<2, dim> &, \
                                                   Tensor<2, dim> &,                \
                                                   SymmetricTensor<2, dim> &,       \
                                                   ArrayView<double>);
  DEALMPM_INSTANTIATE(2)
  DEALMPM_INSTANTIATE(3)
#undef DEALMPM_INSTANTIATE
} // namespace dealmpm
