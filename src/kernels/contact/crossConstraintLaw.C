/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "crossConstraintLaw.H"

#include <cfloat>
#include <cmath>

namespace c4f
{
namespace contact
{

namespace
{

// Results below e*DBL_MIN are flushed to zero: the margin of one in the
// logarithm absorbs the rounding of log/exp, so that nothing returned is
// subnormal and no step raises an underflow
const double logFlush = std::log(DBL_MIN) + 1.0;

// Beyond this exponent a exp(-x) is below DBL_MIN for every finite a
// (log(DBL_MAX) - log(DBL_MIN) is about 1417)
const double xCap = 1500.0;


// x = eps g/lambda >= 0 for eps, g, lambda > 0, capped at xCap and set to
// zero below 1e-304 (exp(-x) rounds to 1 there), formed so that neither
// the product nor the quotient can overflow or underflow
double decayExponent(const double eps, const double g, const double lambda)
{
    const double logEpsG = std::log(eps) + std::log(g);
    const double logX = logEpsG - std::log(lambda);
    if (logX > std::log(xCap))
    {
        return xCap;
    }
    if (logX < -700.0)
    {
        return 0.0;
    }
    if (std::abs(logEpsG) < 700.0)
    {
        // The direct quotient is correctly rounded; only the range check
        // needs the logarithms
        return eps*g/lambda;
    }
    return std::exp(logX);
}


// a exp(-x) for a > 0 finite and 0 <= x <= xCap, flushed to 0 below
// e*DBL_MIN
double scaledDecay(const double a, const double x)
{
    const double logResult = std::log(a) - x;
    if (logResult < logFlush)
    {
        return 0.0;
    }
    if (x <= 700.0)
    {
        // exp(-x) is a normal number here and so is the product
        return a*std::exp(-x);
    }
    return std::exp(logResult);
}

} // End anonymous namespace


NormalLawValue crossConstraintPressure
(
    const double gap,
    const double lambda,
    const double eps
)
{
    // Written as !(lambda > 0) so that a NaN multiplier falls back to the
    // penalty law rather than spreading
    if (!(lambda > 0))
    {
        return penaltyPressure(gap, eps);
    }

    if (gap <= 0)
    {
        return {lambda - eps*gap, -eps, 1.0};
    }

    if (!(eps > 0))
    {
        // The eps -> 0 limit: no decay (the logarithms need eps > 0)
        return {lambda, 0.0, 1.0};
    }

    const double x = decayExponent(eps, gap, lambda);
    // dp/dlambda = d(lambda e^-x)/dlambda with x = eps g/lambda: e^-x (1 + x)
    return {scaledDecay(lambda, x), -scaledDecay(eps, x), scaledDecay(1.0 + x, x)};
}

} // End namespace contact
} // End namespace c4f
