// Unit tests of the pure elasticity kernel, src/kernels/elasticity/hookeLaw.
// References: Timoshenko & Goodier (3rd ed.) for the Lame relations and the
// plane-stress reduction; the tangent is checked against central
// differences of the stress itself.

#include "hookeLaw.H"

#include <gtest/gtest.h>
#include <cmath>
#include <limits>

using namespace c4f::elasticity;

namespace
{

Eigen::Matrix3d sampleGradient()
{
    Eigen::Matrix3d G;
    G << 1.0e-3, -2.0e-4,  3.0e-4,
         5.0e-4,  7.0e-4, -1.0e-4,
        -6.0e-4,  2.0e-4, -4.0e-4;
    return G;
}

} // namespace


TEST(hookeLaw, lameParametersOfSteel)
{
    // E = 200 GPa, nu = 0.3: mu = 76.923 GPa, lambda = 115.385 GPa
    const Lame p = lameFromEngineering(200e9, 0.3, false);
    EXPECT_NEAR(p.mu, 200e9/2.6, 1.0);
    EXPECT_NEAR(p.lambda, 0.3*200e9/(1.3*0.4), 1.0);
    EXPECT_NEAR(implicitStiffness(p), 2*p.mu + p.lambda, 1e-3);
}

TEST(hookeLaw, uniaxialStressRecoversYoungsModulusAndPoisson)
{
    // A strain state with sigma = diag(s, 0, 0) in 3D must have
    // eps_xx = s/E and eps_yy = eps_zz = -nu s/E
    const double E = 70e9, nu = 0.33, s = 1e6;
    const Lame p = lameFromEngineering(E, nu, false);
    Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
    G(0, 0) = s/E;
    G(1, 1) = G(2, 2) = -nu*s/E;
    const Eigen::Matrix3d sig = stress(G, p);
    EXPECT_NEAR(sig(0, 0), s, 1e-6*s);
    EXPECT_NEAR(sig(1, 1), 0, 1e-6*s);
    EXPECT_NEAR(sig(2, 2), 0, 1e-6*s);
}

TEST(hookeLaw, planeStressHasNoOutOfPlaneStressAndRightLateralStrain)
{
    // Plane stress in x-y (z is the out-of-plane axis): uniaxial sigma_xx = s
    // needs eps_xx = s/E, eps_yy = -nu s/E and eps_zz is not a dof (zero).
    const double E = 70e9, nu = 0.33, s = 1e6;
    const Lame p = lameFromEngineering(E, nu, true);
    Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
    G(0, 0) = s/E;
    G(1, 1) = -nu*s/E;
    const Eigen::Matrix3d sig = stress(G, p, 2);
    EXPECT_NEAR(sig(0, 0), s, 1e-6*s);
    EXPECT_NEAR(sig(1, 1), 0, 1e-6*s);
    EXPECT_EQ(sig(2, 2), 0.0);
}

TEST(hookeLaw, stressIsSymmetricAndIgnoresRotation)
{
    const Lame p = lameFromEngineering(1.0, 0.25, false);
    Eigen::Matrix3d W;
    W << 0, 1e-3, -2e-3, -1e-3, 0, 5e-4, 2e-3, -5e-4, 0;
    EXPECT_LT(stress(W, p).norm(), 1e-15);
    const Eigen::Matrix3d s = stress(sampleGradient(), p);
    EXPECT_LT((s - s.transpose()).norm(), 1e-15);
}

TEST(hookeLaw, tangentMatchesCentralDifferences)
{
    const Lame p = lameFromEngineering(210e9, 0.3, false);
    const Eigen::Matrix<double, 9, 9> C = tangent(p);
    const Eigen::Matrix3d G0 = sampleGradient();
    const double h = 1e-7;
    double maxErr = 0;
    for (int b = 0; b < 9; ++b)
    {
        Eigen::Matrix3d dG = Eigen::Matrix3d::Zero();
        dG(b % 3, b/3) = h;
        const Eigen::Matrix3d ds = (stress(G0 + dG, p) - stress(G0 - dG, p))/(2*h);
        for (int a = 0; a < 9; ++a)
        {
            maxErr = std::max(maxErr, std::abs(ds(a % 3, a/3) - C(a, b)));
        }
    }
    // Linear law: central differences are exact up to round-off of
    // sigma ~ 1e8 Pa divided by 2h ~ 2e-7
    EXPECT_LT(maxErr, 1e-4*C.maxCoeff());
}

TEST(hookeLaw, implicitStiffnessIsTheNormalNormalTangent)
{
    // K = n.C:(n n).n for every unit n
    const Lame p = lameFromEngineering(70e9, 0.33, false);
    const Eigen::Matrix<double, 9, 9> C = tangent(p);
    const Eigen::Vector3d ns[] =
        {{1, 0, 0}, {0, 1, 0}, Eigen::Vector3d(1, 2, -2).normalized()};
    for (const auto& n : ns)
    {
        const Eigen::Matrix3d nn = n*n.transpose();
        Eigen::Map<const Eigen::Matrix<double, 9, 1>> vnn(nn.data());
        const Eigen::Matrix<double, 9, 1> vs = C*vnn;
        Eigen::Map<const Eigen::Matrix3d> s(vs.data());
        EXPECT_NEAR(n.dot(s*n), implicitStiffness(p), 1e-6*implicitStiffness(p));
    }
}

TEST(hookeLaw, constantsChecks)
{
    EXPECT_EQ(checkConstants(1e9, 0.3), ConstantsCheck::ok);
    EXPECT_EQ(checkConstants(1e9, -0.99), ConstantsCheck::ok);
    EXPECT_EQ(checkConstants(0, 0.3), ConstantsCheck::nonPositiveE);
    EXPECT_EQ(checkConstants(-1, 0.3), ConstantsCheck::nonPositiveE);
    EXPECT_EQ(checkConstants(1e9, 0.5), ConstantsCheck::nuOutOfRange);
    EXPECT_EQ(checkConstants(1e9, -1.0), ConstantsCheck::nuOutOfRange);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(checkConstants(nan, 0.3), ConstantsCheck::nonPositiveE);
    EXPECT_EQ(checkConstants(1e9, nan), ConstantsCheck::nuOutOfRange);
    EXPECT_NE(describe(ConstantsCheck::nuOutOfRange).find("(-1, 0.5)"), std::string::npos);
}

TEST(hookeLaw, nearIncompressibleStaysFinite)
{
    // nu -> 0.5 makes lambda large but finite; K must follow
    const Lame p = lameFromEngineering(1.0, 0.4999, false);
    EXPECT_TRUE(std::isfinite(p.lambda));
    EXPECT_GT(implicitStiffness(p), 1000.0);
}
