/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "linearizedNormalLaw.H"

#include <cmath>

namespace c4f
{
namespace contact
{

LinearizedNormalLaw linearizeNormalLaw
(
    const NormalLawValue& v,
    const double gap
)
{
    const double epsT = -v.dPressureDGap;

    // Written as !(epsT > 0) so that a NaN slope is not coupled
    if (!(epsT > 0))
    {
        return {false, 0.0, v.pressure};
    }

    if (std::isinf(epsT))
    {
        // An infinitely stiff tangent is the exact constraint; p0 drops out
        // of the coupling when C = 0, and eps_t g* would be inf or NaN
        return {true, 0.0, v.pressure};
    }

    const double compliance = 1.0/epsT;
    if (std::isinf(compliance))
    {
        // A subnormal slope: no spring the matrix could carry
        return {false, 0.0, v.pressure};
    }

    return {true, compliance, v.pressure + epsT*gap};
}

} // End namespace contact
} // End namespace c4f
