/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "bimaterialInterface.H"

namespace c4f
{
namespace elasticity
{

double interfaceConductance(const InterfaceSide& P, const InterfaceSide& N)
{
    return 1.0/(P.d/P.K + N.d/N.K);
}


double explicitTractionWeight(const InterfaceSide& P, const InterfaceSide& N)
{
    const double rP = P.d/P.K;
    return rP/(rP + N.d/N.K);
}


Eigen::Vector3d interfaceDisplacement
(
    const InterfaceSide& P,
    const Eigen::Vector3d& DP,
    const Eigen::Vector3d& tP,
    const InterfaceSide& N,
    const Eigen::Vector3d& DN,
    const Eigen::Vector3d& tN
)
{
    const double a = P.K/P.d;
    const double b = N.K/N.d;
    return (a*DP + b*DN + tN - tP)/(a + b);
}

} // End namespace elasticity
} // End namespace c4f
