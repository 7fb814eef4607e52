/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "nitscheLaw.H"

#include <cmath>

namespace c4f
{
namespace contact
{

double nitscheNormalStress
(
    const double slaveNormalStress,
    const double masterNormalStress
)
{
    return 0.5*(slaveNormalStress + masterNormalStress);
}


double nitscheSlaveWeight
(
    const double slaveStiffness,
    const double masterStiffness
)
{
    // No master stiffness (a face out of reach, where the transfer has no
    // source): the slave's flux alone
    if (!(masterStiffness > 0))
    {
        return 1;
    }
    // In compliances, so that a near-rigid body (k -> infinity) gets
    // weight 0 without an inf/inf
    const double cs = 1/slaveStiffness, cm = 1/masterStiffness;
    return cs/(cs + cm);
}


NitscheValue nitschePressure
(
    const double gap,
    const double normalStress,
    const double gamma
)
{
    const double p = -normalStress - gamma*gap;
    if (p > 0)
    {
        return {p, -gamma, -1.0};
    }
    return {0.0, 0.0, 0.0};
}


double nitscheStabilisation(const double gamma0, const double stiffness)
{
    return gamma0*stiffness;
}


bool validNitscheParameter(const double gamma0)
{
    return gamma0 > 0 && std::isfinite(gamma0);
}


std::string describeNitscheParameterRequirement()
{
    return
        "gamma0 must be a positive, finite number (gamma = gamma0 K/h;"
        " the method is consistent for any gamma0 > 0; 10 is the usual"
        " choice)";
}

} // End namespace contact
} // End namespace c4f
