/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "coulombReturnMap.H"

namespace c4f
{
namespace contact
{

FrictionCheck checkFrictionParameters(const double mu, const double epsT)
{
    // Written so that NaN fails both tests
    if (!(mu >= 0))
    {
        return FrictionCheck::negativeMu;
    }
    if (!(epsT > 0))
    {
        return FrictionCheck::nonPositiveEpsT;
    }
    return FrictionCheck::ok;
}


std::string describe(const FrictionCheck c)
{
    switch (c)
    {
        case FrictionCheck::ok:
            return "valid";
        case FrictionCheck::negativeMu:
            return "friction coefficient mu must be non-negative (mu >= 0;"
                   " mu = 0 is frictionless)";
        case FrictionCheck::nonPositiveEpsT:
            return "tangential penalty eps_T must be positive (eps_T > 0)";
    }
    return "unknown";
}


Eigen::Vector3d slipIncrement
(
    const Eigen::Vector3d& n,
    const Eigen::Vector3d& dDslave,
    const Eigen::Vector3d& dDmaster
)
{
    // Subtract first so that a common rigid translation cancels exactly
    const Eigen::Vector3d d = dDslave - dDmaster;
    return d - n*n.dot(d);
}


CoulombResult coulombReturnMap
(
    const Eigen::Vector3d& n,
    const Eigen::Vector3d& tTold,
    const Eigen::Vector3d& xi,
    const double pN,
    const double mu,
    const double epsT
)
{
    const Eigen::Matrix3d P =
        Eigen::Matrix3d::Identity() - n*n.transpose();

    // Projecting the whole trial (not only tTold) keeps t_T tangential
    // for any xi and makes -eps_T P the exact stick derivative
    const Eigen::Vector3d tTrial = P*(tTold - epsT*xi);
    const double trialNorm = tTrial.norm();

    // A tensile or NaN pressure means the faces are apart: no friction
    const double bound = (pN > 0) ? mu*pN : 0.0;

    CoulombResult r;
    r.trial = tTrial;
    r.bound = bound;

    if (!(bound > 0))
    {
        // t_T vanishes for every xi, so its derivative does too
        r.traction.setZero();
        r.slip = trialNorm > 0;
        r.slipIncrementMagnitude = r.slip ? trialNorm/epsT : 0.0;
        r.tangent.setZero();
        return r;
    }

    if (trialNorm <= bound)
    {
        r.traction = tTrial;
        r.slip = false;
        r.slipIncrementMagnitude = 0;
        r.tangent = -epsT*P;
        return r;
    }

    // Here trialNorm > bound > 0, so the division is safe
    const Eigen::Vector3d m = tTrial/trialNorm;
    r.traction = bound*m;
    r.slip = true;
    r.slipIncrementMagnitude = (trialNorm - bound)/epsT;
    r.tangent = -(bound*epsT/trialNorm)*(P - m*m.transpose());
    return r;
}

} // End namespace contact
} // End namespace c4f
