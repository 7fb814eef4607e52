/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "augmentedLagrangeLaw.H"

namespace c4f
{
namespace contact
{

NormalLawValue augmentedLagrangePressure
(
    const double gap,
    const double lambda,
    const double eps
)
{
    const double trial = lambda - eps*gap;
    if (trial > 0)
    {
        return {trial, -eps, 1.0};
    }
    // Also taken for a NaN trial: no pressure rather than a NaN one
    return {0.0, 0.0};
}


double uzawaUpdate(const double lambda, const double gap, const double eps)
{
    return augmentedLagrangePressure(gap, lambda, eps).pressure;
}


bool uzawaConverged
(
    const double maxPenetration,
    const double h,
    const double penetrationTol,
    const double dLambdaMax,
    const double lambdaMax,
    const double multiplierTol
)
{
    // Written as <= so that 0 <= tol*0 holds: a contact-free problem
    // (no multiplier, no change) is converged without a special case
    return
        maxPenetration <= penetrationTol*h
     && dLambdaMax <= multiplierTol*lambdaMax;
}

} // End namespace contact
} // End namespace c4f
