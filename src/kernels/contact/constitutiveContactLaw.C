/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "constitutiveContactLaw.H"

#include <cfloat>
#include <cmath>

namespace c4f
{
namespace contact
{

namespace
{

// A margin of one in the logarithm keeps every value formed below inside
// [e DBL_MIN, DBL_MAX/e], whatever the rounding of log, pow and exp
const double logFloor = std::log(DBL_MIN) + 1.0;
const double logCeiling = std::log(DBL_MAX) - 1.0;


// factor c x^m for factor, c, x > 0 finite: flushed to 0 below the
// smallest normal double and saturated at DBL_MAX above the largest
double scaledPower
(
    const double factor,
    const double c,
    const double x,
    const double m
)
{
    const double logPow = m*std::log(x);
    const double logCPow = std::log(c) + logPow;
    const double logResult = std::log(factor) + logCPow;
    if (logResult < logFloor)
    {
        return 0.0;
    }
    if (logResult > logCeiling)
    {
        return DBL_MAX;
    }
    if (std::abs(logPow) < 700.0 && std::abs(logCPow) < 700.0)
    {
        // Every intermediate is a normal number: take the direct
        // (correctly rounded) form rather than exp of a logarithm
        return factor*(c*std::pow(x, m));
    }
    return std::exp(logResult);
}

} // End anonymous namespace


NormalLawValue constitutivePressure
(
    const double gap,
    const double cN,
    const double n
)
{
    if (!(gap < 0))
    {
        return {0.0, 0.0};
    }
    if (n == 1)
    {
        return penaltyPressure(gap, cN);
    }
    const double penetration = -gap;
    return
    {
        scaledPower(1.0, cN, penetration, n),
       -scaledPower(n, cN, penetration, n - 1)
    };
}


double constitutiveGapForPressure
(
    const double pressure,
    const double cN,
    const double n
)
{
    // isgreater: a quiet comparison, NaN raises no invalid-operation flag
    if (!std::isgreater(pressure, 0.0) || std::isinf(pressure))
    {
        return std::isinf(pressure) && pressure > 0 ? -DBL_MAX : 0.0;
    }
    // (p/c_N)^(1/n), range-checked in logarithms: p/c_N may underflow (a
    // stiff law) or overflow where its n-th root does not
    const double logRatio = std::log(pressure) - std::log(cN);
    const double logResult = logRatio/n;
    if (logResult < logFloor)
    {
        return 0.0;
    }
    if (logResult > logCeiling)
    {
        return -DBL_MAX;
    }
    if (std::abs(logRatio) < 700.0)
    {
        return -std::pow(pressure/cN, 1.0/n);
    }
    return -std::exp(logResult);
}


bool validConstitutiveLaw(const double cN, const double n)
{
    return
        cN > 0 && std::isfinite(cN)
     && n > 0 && std::isfinite(n);
}


std::string describeConstitutiveLawRequirement()
{
    return
        "c_N and n both positive and finite"
        " (n of about 2-3.33 for rough surfaces; n = 1 is the penalty law)";
}

} // End namespace contact
} // End namespace c4f
