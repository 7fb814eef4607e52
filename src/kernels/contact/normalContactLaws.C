/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "normalContactLaws.H"

#include <cmath>
#include <stdexcept>

namespace c4f
{
namespace contact
{

NormalLawValue penaltyPressure(const double gap, const double epsN)
{
    if (gap < 0)
    {
        return {-epsN*gap, -epsN};
    }
    return {0.0, 0.0};
}


double stiffnessScaledPenalty(const double scale, const double K, const double h)
{
    return scale*K/h;
}


bool validPenalty(const double value)
{
    return value > 0 && std::isfinite(value);
}


std::string describePenaltyRequirement()
{
    return "a positive, finite number";
}


bool waitsAtFirstContact
(
    const double gap,
    const double deepestPenetration,
    const double h
)
{
    return
        deepestPenetration > firstContactRoundOff*h
     && gap < 0
     && -gap < firstContactDepthFraction*deepestPenetration;
}


bool activeByPrimalDual(const double lambdaN, const double gap, const double c)
{
    return lambdaN - c*gap > 0;
}


ComplementarityValue primalDualComplementarity
(
    const double lambdaN,
    const double gap,
    const double c
)
{
    if (activeByPrimalDual(lambdaN, gap, c))
    {
        return {c*gap, 0.0, c};
    }
    return {lambdaN, 1.0, 0.0};
}


int updateActiveSet
(
    const std::vector<double>& lambdaN,
    const std::vector<double>& gap,
    const double c,
    std::vector<char>& active
)
{
    if (lambdaN.size() != gap.size() || gap.size() != active.size())
    {
        throw std::invalid_argument("updateActiveSet: sizes differ");
    }
    int changes = 0;
    for (std::size_t i = 0; i < gap.size(); ++i)
    {
        const char now = activeByPrimalDual(lambdaN[i], gap[i], c);
        changes += (now != active[i]);
        active[i] = now;
    }
    return changes;
}

} // End namespace contact
} // End namespace c4f
