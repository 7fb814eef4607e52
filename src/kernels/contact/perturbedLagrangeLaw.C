/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "perturbedLagrangeLaw.H"

#include <algorithm>

namespace c4f
{
namespace contact
{

double perturbedLagrangeUpdate
(
    const double lambda,
    const double gap,
    const double eps,
    const double Kc
)
{
    // Compliances rather than stiffnesses, so that eps = inf (the
    // Lagrange-multiplier limit) is an ordinary input
    const double step =
        perturbedLagrangeResidual(lambda, gap, eps)/(1.0/Kc + 1.0/eps);
    return std::max(0.0, lambda + step);
}


NormalLawValue perturbedLagrangeStepPressure
(
    const double gap,
    const double lambda,
    const double eps,
    const double Kc
)
{
    const double p = perturbedLagrangeUpdate(lambda, gap, eps, Kc);
    if (!(p > 0))
    {
        return {0.0, 0.0};
    }
    // p = lambda + (-g - lambda/eps) k, k = 1/(1/Kc + 1/eps): dp/dlambda is
    // 1 - k/eps = k/Kc, which tends to 1 as eps -> infinity (exact)
    const double k = 1.0/(1.0/Kc + 1.0/eps);
    return {p, -k, k/Kc};
}


double perturbedLagrangeResidual
(
    const double lambda,
    const double gap,
    const double eps
)
{
    return -gap - lambda/eps;
}

} // End namespace contact
} // End namespace c4f
