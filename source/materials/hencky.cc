#include <dealmpm/materials/hencky.h>

#include <Eigen/Eigenvalues>
#include <cmath>

namespace dealmpm
{
  PrincipalStrain
  principal_log_strain(const SymmetricTensor<2, 3> &b)
  {
    Eigen::Matrix3d m;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        m(i, j) = b[i][j];
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m);
    PrincipalStrain                                      p;
    for (unsigned int a = 0; a < 3; ++a)
      {
        // A non-positive eigenvalue (J <= 0) gives NaN: the step's
        // finiteness check then stops the run and names the particle.
        p.strain[a] = 0.5 * std::log(solver.eigenvalues()(a));
        for (unsigned int i = 0; i < 3; ++i)
          p.direction[a][i] = solver.eigenvectors()(i, a);
      }
    return p;
  }

  SymmetricTensor<2, 3>
  from_principal(const std::array<double, 3>       &values,
                 const std::array<Tensor<1, 3>, 3> &direction)
  {
    SymmetricTensor<2, 3> t;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          t[i][j] += values[a] * direction[a][i] * direction[a][j];
    return t;
  }
} // namespace dealmpm
