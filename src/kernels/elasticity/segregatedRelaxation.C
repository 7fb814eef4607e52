/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "segregatedRelaxation.H"

#include <algorithm>
#include <cmath>

double c4f::elasticity::volumetricStiffnessRatio
(
    const double normalStressSum,
    const double K
)
{
    if (!(K > 0) || !std::isfinite(K) || !std::isfinite(normalStressSum))
    {
        return 0;
    }
    return normalStressSum/K;
}


double c4f::elasticity::volumetricModeFactor
(
    const double q,
    const double omega
)
{
    return 1 - omega*q;
}


double c4f::elasticity::volumetricModeRelaxation
(
    const double q,
    const double rho
)
{
    if
    (
        !std::isfinite(q)
     || !(q > volumetricModeUnstable*(1 + volumetricModeTolerance))
    )
    {
        return 1;
    }
    return std::min(1.0, (1 + rho)/q);
}


double c4f::elasticity::isotropicVolumetricStiffnessRatio
(
    const double nu,
    const int nDirections
)
{
    return 1 + (nDirections - 1)*nu/(1 - nu);
}
