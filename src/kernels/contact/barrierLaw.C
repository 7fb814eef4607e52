/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "barrierLaw.H"

#include <cfloat>
#include <cmath>

namespace c4f
{
namespace contact
{

namespace
{

// An overflowed magnitude saturates at the largest double
double saturate(const double v)
{
    return std::isinf(v) ? std::copysign(DBL_MAX, v) : v;
}

} // End anonymous namespace


BarrierValue barrier(const double d, const double dhat)
{
    if (!(d > 0))
    {
        return {DBL_MAX, -DBL_MAX, DBL_MAX};
    }
    if (!(d < dhat))
    {
        return {0.0, 0.0, 0.0};
    }

    // x = d/dhat in (0, 1), u = 1 - x formed from the difference, so that
    // it keeps its digits near dhat; ln x = log1p(-u)
    const double x = d/dhat;
    const double u = (dhat - d)/dhat;
    const double lnx = x < 0.5 ? std::log(x) : std::log1p(-u);

    const double b = saturate(-dhat*dhat*u*u*lnx);
    const double db = saturate(dhat*u*(2*lnx - u/x));
    const double d2b = saturate(u*(3*x + 1)/(x*x) - 2*lnx);
    return {b, db, d2b};
}


NormalLawValue barrierPressure
(
    const double gap,
    const double dhat,
    const double kappa
)
{
    const BarrierValue v = barrier(gap, dhat);
    return {saturate(-kappa*v.db), saturate(-kappa*v.d2b)};
}


double barrierInitialStiffness
(
    const double scale,
    const double K,
    const double h
)
{
    return stiffnessScaledPenalty(scale, K, h);
}


double barrierStepLimit
(
    const double gapBefore,
    const double gapAfter,
    const double fraction
)
{
    // Written so that a NaN gap falls through to 1
    if (!(gapBefore > 0) || !(gapAfter < fraction*gapBefore))
    {
        return 1.0;
    }
    // gapAfter < fraction gapBefore < gapBefore: the denominator is
    // positive, and alpha in (0, 1)
    const double alpha = (1 - fraction)*gapBefore/(gapBefore - gapAfter);
    return alpha < 1 ? alpha : 1.0;
}


bool barrierStiffnessShouldIncrease
(
    const double previousMinGap,
    const double minGap,
    const double floorGap
)
{
    return minGap < floorGap && minGap < previousMinGap;
}


bool validBarrierLength(const double dhat)
{
    return dhat > 0 && std::isfinite(dhat);
}


bool validBarrierScale(const double scale)
{
    return scale > 0 && std::isfinite(scale);
}


bool validBarrierFraction(const double f)
{
    return f > 0 && f < 1;
}


std::string describeBarrierLengthRequirement()
{
    return
        "a positive, finite length [m], much smaller than the cell size"
        " (about 1e-3 h)";
}


std::string describeBarrierScaleRequirement()
{
    return "a positive, finite number";
}


std::string describeBarrierFractionRequirement()
{
    return "a fraction strictly between 0 and 1";
}

} // End namespace contact
} // End namespace c4f
