/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "forceControl.H"

#include <algorithm>
#include <cmath>
#include <stdexcept>

double c4f::rigid::forceControlSlope
(
    const ForceControlState& st,
    const double k0
)
{
    if (st.havePrev)
    {
        const double ds = st.s - st.sPrev;
        // A step below round-off of s says nothing about the slope
        if (std::abs(ds) > 1e-14*std::max(std::abs(st.s), std::abs(st.sPrev)))
        {
            const double k = (st.P - st.PPrev)/ds;
            if (std::isfinite(k) && k > 0)
            {
                return k;
            }
        }
    }
    return k0;
}


double c4f::rigid::forceControlUpdate
(
    const ForceControlState& st,
    const double Ptarget,
    const double k0,
    const double maxStep
)
{
    if (!(k0 > 0) || !std::isfinite(k0) || !(maxStep > 0) || !std::isfinite(maxStep))
    {
        throw std::invalid_argument
        (
            "forceControlUpdate: k0 and maxStep must be positive and finite"
        );
    }
    const double k = forceControlSlope(st, k0);
    const double ds = std::clamp((Ptarget - st.P)/k, -maxStep, maxStep);
    return st.s + ds;
}


bool c4f::rigid::forceControlConverged
(
    const double P,
    const double Ptarget,
    const double tol
)
{
    const double scale = Ptarget != 0 ? std::abs(Ptarget) : 1.0;
    return std::abs(P - Ptarget) <= tol*scale;
}
