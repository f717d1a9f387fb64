#include <dealmpm/materials/tait_fluid.h>

#include <cmath>

namespace dealmpm
{
  template <int dim>
  TaitFluid<dim>::TaitFluid(const TaitParameters &parameters)
    : parameters(parameters)
  {}

  template <int dim>
  std::vector<FieldDescription>
  TaitFluid<dim>::internal_variables() const
  {
    std::vector<FieldDescription> fields = {{"viscous_work", 1}};
    if (dim == 2)
      fields.push_back({"stress_zz", 1});
    return fields;
  }

  template <int dim>
  double
  TaitFluid<dim>::pressure(const double J) const
  {
    const double B = this->density * parameters.sound_speed *
                     parameters.sound_speed / parameters.exponent;
    const double p = B * (std::pow(J, -parameters.exponent) - 1.);
    return parameters.tension_cut_off ? std::max(p, 0.) : p;
  }

  template <int dim>
  void
  TaitFluid<dim>::update_stress(const Tensor<2, dim>    &L,
                                const Tensor<2, dim>    &F,
                                const double             dt,
                                SymmetricTensor<2, dim> &stress,
                                ArrayView<double>        internal) const
  {
    const double J = determinant(F);
    // dev(D) in 3D: D_zz = 0 in plane strain, so tr D is the in-plane trace.
    const SymmetricTensor<2, dim> D          = symmetrize(L);
    const double                  trace_D    = trace(D);
    SymmetricTensor<2, dim>       deviatoric = D;
    for (unsigned int d = 0; d < dim; ++d)
      deviatoric[d][d] -= trace_D / 3.;
    const double p = pressure(J);
    stress =
      2. * parameters.viscosity * deviatoric - p * unit_symmetric_tensor<dim>();
    // Viscous power J 2 mu dev(D) : dev(D) per unit reference volume
    // (the zz entry of dev(D) counts in plane strain).
    const double zz = -trace_D / 3.;
    internal[0] += dt * J * 2. * parameters.viscosity *
                   (deviatoric * deviatoric + (dim == 2 ? zz * zz : 0.));
    if constexpr (dim == 2)
      internal[1] = 2. * parameters.viscosity * zz - p;
  }

  template <int dim>
  double
  TaitFluid<dim>::wave_speed(const Tensor<2, dim> &F) const
  {
    return parameters.sound_speed *
           std::pow(determinant(F), -(parameters.exponent - 1.) / 2.);
  }

  template <int dim>
  double
  TaitFluid<dim>::out_of_plane_stress(const Tensor<2, dim> &,
                                      const SymmetricTensor<2, dim> &,
                                      ArrayView<const double> internal) const
  {
    return dim == 2 ? internal[1] : 0.;
  }

  template <int dim>
  double
  TaitFluid<dim>::strain_energy_density(const Tensor<2, dim> &F,
                                        const SymmetricTensor<2, dim> &,
                                        ArrayView<const double>) const
  {
    // -int_1^J B (s^-gamma - 1) ds; zero in tension with the cut-off.
    const double J = determinant(F);
    if (parameters.tension_cut_off && J >= 1.)
      return 0.;
    const double gamma = parameters.exponent;
    const double B =
      this->density * parameters.sound_speed * parameters.sound_speed / gamma;
    return B * ((std::pow(J, 1. - gamma) - 1.) / (gamma - 1.) + (J - 1.));
  }

  template class TaitFluid<2>;
  template class TaitFluid<3>;

  namespace
  {
    void
    declare_tait_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Sound speed",
                        "50",
                        Patterns::Double(),
                        "c0 (m/s), > 0: about 10 times the fastest flow keeps "
                        "the density within 1 % (weakly compressible); the "
                        "time step scales with 1 / c0.");
      prm.declare_entry("Exponent",
                        "7",
                        Patterns::Double(),
                        "gamma of Tait's equation p = B (J^-gamma - 1), "
                        "> 1 (7 for water).");
      prm.declare_entry("Viscosity",
                        "1e-3",
                        Patterns::Double(),
                        "Dynamic viscosity mu (Pa s), >= 0 (1e-3 for water).");
      prm.declare_entry("Tension cut-off",
                        "true",
                        Patterns::Bool(),
                        "No negative pressure (free surfaces do not pull).");
    }

    TaitParameters
    read_tait(SceneReader &reader)
    {
      TaitParameters t;
      t.sound_speed = reader.get_positive("Sound speed");
      t.exponent    = reader.get_double("Exponent");
      if (!(t.exponent > 1))
        reader.fail("Exponent", "a number > 1");
      t.viscosity       = reader.get_nonnegative("Viscosity");
      t.tension_cut_off = reader.get_bool("Tension cut-off");
      return t;
    }
  } // namespace

  template <int dim>
  void
  add_tait_fluid_material(Registry<Material<dim>> &registry)
  {
    registry.add(
      "Tait fluid",
      "weakly compressible Newtonian fluid: Tait's equation of state "
      "from J, viscous stress 2 mu dev(D), optional tension cut-off; F "
      "is reset to J^(1/dim) I (Sound speed, Exponent, Viscosity, "
      "Tension cut-off).",
      declare_tait_parameters,
      [](SceneReader &reader) -> std::unique_ptr<Material<dim>> {
        return std::make_unique<TaitFluid<dim>>(read_tait(reader));
      });
  }

  template void
  add_tait_fluid_material(Registry<Material<2>> &);
  template void
  add_tait_fluid_material(Registry<Material<3>> &);
} // namespace dealmpm
