/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "aitkenRelaxation.H"

#include <algorithm>
#include <cmath>

double c4f::coupling::aitkenFactor
(
    const double omegaPrev,
    const AitkenSums& sums,
    const double omegaMin,
    const double omegaMax
)
{
    if (!(sums.diffSqr > 0) || !std::isfinite(sums.diffSqr))
    {
        return std::clamp(omegaPrev, omegaMin, omegaMax);
    }

    const double omega = -omegaPrev*sums.rPrevDotDiff/sums.diffSqr;

    return std::clamp(omega, omegaMin, omegaMax);
}
