/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "hookeLaw.H"

namespace c4f
{
namespace elasticity
{

ConstantsCheck checkConstants(const double E, const double nu)
{
    // Written so that NaN fails both tests
    if (!(E > 0))
    {
        return ConstantsCheck::nonPositiveE;
    }
    if (!(nu > -1.0 && nu < 0.5))
    {
        return ConstantsCheck::nuOutOfRange;
    }
    return ConstantsCheck::ok;
}


std::string describe(const ConstantsCheck c)
{
    switch (c)
    {
        case ConstantsCheck::ok:
            return "valid";
        case ConstantsCheck::nonPositiveE:
            return "Young's modulus E must be positive (E > 0)";
        case ConstantsCheck::nuOutOfRange:
            return "Poisson's ratio nu must lie in the open interval"
                   " (-1, 0.5) for a positive-definite strain energy";
    }
    return "unknown";
}


Lame lameFromEngineering(const double E, const double nu, const bool planeStress)
{
    Lame p;
    p.mu = E/(2.0*(1.0 + nu));
    p.lambda =
        planeStress
      ? nu*E/((1.0 + nu)*(1.0 - nu))
      : nu*E/((1.0 + nu)*(1.0 - 2.0*nu));
    return p;
}


double implicitStiffness(const Lame& p)
{
    return 2.0*p.mu + p.lambda;
}


Eigen::Matrix3d stress
(
    const Eigen::Matrix3d& gradD,
    const Lame& p,
    const int planeStressAxis
)
{
    Eigen::Matrix3d s =
        p.mu*(gradD + gradD.transpose())
      + p.lambda*gradD.trace()*Eigen::Matrix3d::Identity();

    if (planeStressAxis >= 0 && planeStressAxis < 3)
    {
        s(planeStressAxis, planeStressAxis) = 0;
    }
    return s;
}


Eigen::Matrix<double, 9, 9> tangent(const Lame& p)
{
    // C_ijkl = mu (d_ik d_jl + d_il d_jk) + lambda d_ij d_kl, mapped to
    // column-major indices a = i + 3j, b = k + 3l
    Eigen::Matrix<double, 9, 9> C = Eigen::Matrix<double, 9, 9>::Zero();
    for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l)
    {
        const double dik = (i == k), djl = (j == l);
        const double dil = (i == l), djk = (j == k);
        const double dij = (i == j), dkl = (k == l);
        C(i + 3*j, k + 3*l) =
            p.mu*(dik*djl + dil*djk) + p.lambda*dij*dkl;
    }
    return C;
}

} // End namespace elasticity
} // End namespace c4f
