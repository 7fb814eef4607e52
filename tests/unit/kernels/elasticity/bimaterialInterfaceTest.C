// Unit tests of the bonded bi-material interface kernel,
// src/kernels/elasticity/bimaterialInterface. The reference is the exact
// face state of a piecewise-linear displacement: a traction t is carried
// across the face, each cell's normal gradient is (t - t_X)/K_X, and the
// kernel must return that state's face displacement and traction for
// stiffness ratios from 1e-6 to 1e6 and distances down to 1e-12 of the
// other side's.

#include "bimaterialInterface.H"

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <vector>

using namespace c4f::elasticity;

namespace
{

const std::vector<double> ratios{1e-6, 1e-3, 0.1, 0.5, 1.0, 3.0, 1e3, 1e6};
const std::vector<double> distances{1e-12, 1e-3, 0.3, 1.0, 7.0};

Eigen::Vector3d sampleTraction()
{
    return Eigen::Vector3d(2.5e6, -7.0e5, 1.0e5);
}

//- Face traction from side P's half cell, n from P to N
Eigen::Vector3d tractionP
(
    const InterfaceSide& P, const Eigen::Vector3d& DP,
    const Eigen::Vector3d& tP, const Eigen::Vector3d& Df
)
{
    return P.K*(Df - DP)/P.d + tP;
}

//- Face traction from side N's half cell
Eigen::Vector3d tractionN
(
    const InterfaceSide& N, const Eigen::Vector3d& DN,
    const Eigen::Vector3d& tN, const Eigen::Vector3d& Df
)
{
    return N.K*(DN - Df)/N.d + tN;
}

//- Magnitude of the terms a face traction sums: K/d times a displacement
//  (a difference of two nearly equal values when d is tiny) plus the
//  explicit tractions; round-off is relative to it, not to the result
double roundOffScale
(
    const InterfaceSide& P, const InterfaceSide& N,
    const Eigen::Vector3d& DP, const Eigen::Vector3d& DN,
    const Eigen::Vector3d& tP, const Eigen::Vector3d& tN
)
{
    return
        std::max(P.K/P.d, N.K/N.d)*(DP.norm() + DN.norm())
      + tP.norm() + tN.norm();
}

} // namespace


TEST(bimaterialInterface, exactPiecewiseLinearStateIsReproduced)
{
    const double KP = 2.0e11;
    const Eigen::Vector3d t = sampleTraction();
    const Eigen::Vector3d Df(1e-4, -3e-5, 2e-6);
    const Eigen::Vector3d tP(4.0e5, -1.0e5, 0.0);
    const Eigen::Vector3d tN(-2.0e5, 3.0e5, 5.0e4);

    for (const double r : ratios)
    for (const double dP : distances)
    for (const double dN : distances)
    {
        const InterfaceSide P{KP, dP}, N{r*KP, dN};
        const Eigen::Vector3d DP = Df - dP*(t - tP)/P.K;
        const Eigen::Vector3d DN = Df + dN*(t - tN)/N.K;

        const Eigen::Vector3d D = interfaceDisplacement(P, DP, tP, N, DN, tN);
        const double scale = DP.norm() + DN.norm() + Df.norm();
        EXPECT_LE((D - Df).norm(), 1e-12*scale)
            << "K_N/K_P " << r << " dP " << dP << " dN " << dN;

        // The face traction of the scheme, implicit Laplacian plus the
        // weighted explicit part, is the carried traction
        const double w = explicitTractionWeight(P, N);
        const Eigen::Vector3d flux =
            interfaceConductance(P, N)*(DN - DP) + w*tP + (1 - w)*tN;
        EXPECT_LE((flux - t).norm(), 1e-12*roundOffScale(P, N, DP, DN, tP, tN))
            << "K_N/K_P " << r << " dP " << dP << " dN " << dN;
    }
}

TEST(bimaterialInterface, bothSidesGiveTheFluxForAnyCellValues)
{
    // Not only at the exact state: for arbitrary cell values the face
    // displacement balances the two half-cell tractions, and the scheme's
    // flux equals them (the consistency the explicit weight exists for)
    const Eigen::Vector3d DP(3e-4, 1e-5, -2e-5), DN(-1e-4, 4e-5, 7e-6);
    const Eigen::Vector3d tP(1.0e6, 0.0, -3.0e5), tN(-5.0e5, 2.0e5, 0.0);

    for (const double r : ratios)
    for (const double dP : distances)
    for (const double dN : distances)
    {
        const InterfaceSide P{7.0e10, dP}, N{r*7.0e10, dN};
        const Eigen::Vector3d Df = interfaceDisplacement(P, DP, tP, N, DN, tN);
        const Eigen::Vector3d fP = tractionP(P, DP, tP, Df);
        const Eigen::Vector3d fN = tractionN(N, DN, tN, Df);
        const double w = explicitTractionWeight(P, N);
        const Eigen::Vector3d flux =
            interfaceConductance(P, N)*(DN - DP) + w*tP + (1 - w)*tN;
        const double scale = roundOffScale(P, N, DP, DN, tP, tN);
        EXPECT_LE((fP - fN).norm(), 1e-12*scale)
            << "K_N/K_P " << r << " dP " << dP << " dN " << dN;
        EXPECT_LE((flux - fP).norm(), 1e-12*scale)
            << "K_N/K_P " << r << " dP " << dP << " dN " << dN;
    }
}

TEST(bimaterialInterface, equalStiffnessIsLinearInterpolation)
{
    // One material, equal explicit tractions: D_f is the linear interpolate
    // (weight d_N/d of P), the conductance K/d, the weight d_P/d
    const Eigen::Vector3d DP(1.0, 2.0, 3.0), DN(-4.0, 0.5, 6.0);
    const Eigen::Vector3d tc(3.0e5, -1.0e5, 0.0);
    for (const double dP : distances)
    for (const double dN : distances)
    {
        const InterfaceSide P{1.5e11, dP}, N{1.5e11, dN};
        const double d = dP + dN;
        const Eigen::Vector3d D = interfaceDisplacement(P, DP, tc, N, DN, tc);
        EXPECT_LE((D - (dN*DP + dP*DN)/d).norm(), 1e-12*(DP.norm() + DN.norm()));
        EXPECT_NEAR(interfaceConductance(P, N), 1.5e11/d, 1e-12*1.5e11/d);
        EXPECT_NEAR(explicitTractionWeight(P, N), dP/d, 1e-14);
    }
}

TEST(bimaterialInterface, rigidSideTakesTheFace)
{
    // K_P -> infinity: the face moves with P, and the flux is N's half cell
    // traction with N's own explicit part (w_P -> 0)
    const InterfaceSide P{1e30, 0.5}, N{1e9, 0.5};
    const Eigen::Vector3d DP(1e-3, 0, 0), DN(2e-3, 0, 0);
    const Eigen::Vector3d tP(1e6, 0, 0), tN(-1e6, 0, 0);
    const Eigen::Vector3d D = interfaceDisplacement(P, DP, tP, N, DN, tN);
    EXPECT_NEAR(D.x(), DP.x(), 1e-15);
    EXPECT_NEAR(explicitTractionWeight(P, N), 0.0, 1e-20);
}
