// Unit tests of src/kernels/elasticity/segregatedRelaxation: the Jacobi
// splitting of the normal stresses by K, built here from Hooke's law
// (hookeLaw.H) and its eigenvalues taken by Eigen, is what the kernel's
// closed forms say; the relaxation holds its volumetric mode to the
// bound over Poisson's ratio in 2D and 3D, and degenerate inputs leave the
// correctors unrelaxed.

#include "segregatedRelaxation.H"
#include "hookeLaw.H"

#include <gtest/gtest.h>
#include <Eigen/Dense>
#include <cmath>
#include <limits>

using namespace c4f::elasticity;

namespace
{

// The normal-stress block C_ij = d sigma_ii / d e_jj of n solved
// directions, from Hooke's law itself (unit strain along e_jj)
Eigen::MatrixXd normalStiffness(const Lame& p, const int n)
{
    Eigen::MatrixXd C(n, n);
    for (int j = 0; j < n; ++j)
    {
        Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
        G(j, j) = 1;
        const Eigen::Matrix3d s = stress(G, p);
        for (int i = 0; i < n; ++i)
        {
            C(i, j) = s(i, i);
        }
    }
    return C;
}

// Spectral radius of the relaxed corrector on uniform strains,
// I - omega C/K
double spectralRadius(const Eigen::MatrixXd& C, const double K, const double omega)
{
    const Eigen::MatrixXd M =
        Eigen::MatrixXd::Identity(C.rows(), C.cols()) - omega*C/K;
    return M.eigenvalues().cwiseAbs().maxCoeff();
}

} // namespace


TEST(segregatedRelaxation, volumetricEigenvalueIsOneMinusQ)
{
    for (const int n : {2, 3})
    {
        for (const double nu : {0.0, 0.25, 0.3, 0.45, 0.49})
        {
            const Lame p = lameFromEngineering(1e6, nu, false);
            const double K = implicitStiffness(p);
            const Eigen::MatrixXd C = normalStiffness(p, n);
            const double q = volumetricStiffnessRatio(C.row(0).sum(), K);
            EXPECT_NEAR(q, isotropicVolumetricStiffnessRatio(nu, n), 1e-12);
            // The uniform mode e_1 = ... = e_n is an eigenvector of I - C/K
            const Eigen::VectorXd ones = Eigen::VectorXd::Ones(n);
            const Eigen::VectorXd Mv =
                ones - C*ones/K;
            EXPECT_NEAR(Mv(0), volumetricModeFactor(q, 1), 1e-12);
            EXPECT_NEAR((Mv - Mv(0)*ones).norm(), 0, 1e-12);
        }
    }
}


TEST(segregatedRelaxation, unrelaxedThreeDimensionalModeGrowsAboveOneThird)
{
    // The measured threshold (docs/solver.md): 3D nu = 0.3 converged
    // plainly, 0.35 did not; plane strain never diverges
    for (const double nu : {0.0, 0.2, 0.3, 0.33})
    {
        const Lame p = lameFromEngineering(1e6, nu, false);
        EXPECT_LT(spectralRadius(normalStiffness(p, 3), implicitStiffness(p), 1), 1)
            << "nu = " << nu;
    }
    for (const double nu : {0.34, 0.35, 0.4, 0.45, 0.49})
    {
        const Lame p = lameFromEngineering(1e6, nu, false);
        EXPECT_GT(spectralRadius(normalStiffness(p, 3), implicitStiffness(p), 1), 1)
            << "nu = " << nu;
    }
    for (const double nu : {0.3, 0.45, 0.49, 0.4999})
    {
        const Lame p = lameFromEngineering(1e6, nu, false);
        EXPECT_LT(spectralRadius(normalStiffness(p, 2), implicitStiffness(p), 1), 1)
            << "nu = " << nu;
    }
}


TEST(segregatedRelaxation, relaxedModeHeldToTheBoundOverPoissonsRatio)
{
    for (const int n : {2, 3})
    {
        for (int k = 0; k <= 1000; ++k)
        {
            const double nu = 0.4999*k/1000;
            const Lame p = lameFromEngineering(2e11, nu, false);
            const double K = implicitStiffness(p);
            const Eigen::MatrixXd C = normalStiffness(p, n);
            const double q = volumetricStiffnessRatio(C.row(0).sum(), K);
            const double omega = volumetricModeRelaxation(q);

            ASSERT_GT(omega, 0);
            ASSERT_LE(omega, 1);
            // Every mode contracts
            EXPECT_LT(spectralRadius(C, K, omega), 1)
                << "n = " << n << ", nu = " << nu;
            if (omega < 1)
            {
                // A growing mode, held to exactly the bound: the largest
                // such omega
                EXPECT_GT(q, volumetricModeUnstable);
                EXPECT_NEAR
                (
                    volumetricModeFactor(q, omega), -volumetricModeBound, 1e-12
                ) << "n = " << n << ", nu = " << nu;
            }
            else
            {
                // Left alone only where the mode does not grow
                EXPECT_LE
                (
                    std::abs(volumetricModeFactor(q, 1)),
                    1 + volumetricModeTolerance*volumetricModeUnstable
                ) << "n = " << n << ", nu = " << nu;
            }
        }
    }
}


TEST(segregatedRelaxation, unchangedUpToOneThirdIn3DAndInPlaneStrain)
{
    for (const double nu : {0.0, 0.1, 0.25, 0.3, 1.0/3.0})
    {
        EXPECT_EQ
        (
            volumetricModeRelaxation(isotropicVolumetricStiffnessRatio(nu, 3)),
            1
        ) << nu;
    }
    for (const double nu : {0.0, 0.3, 0.45, 0.49, 0.4999})
    {
        EXPECT_EQ
        (
            volumetricModeRelaxation(isotropicVolumetricStiffnessRatio(nu, 2)),
            1
        ) << nu;
    }
    // The closed form above the threshold: (5/3)(1 - nu)/(1 + nu) in 3D
    for (const double nu : {0.34, 0.45, 0.49})
    {
        EXPECT_NEAR
        (
            volumetricModeRelaxation(isotropicVolumetricStiffnessRatio(nu, 3)),
            (5.0/3.0)*(1 - nu)/(1 + nu),
            1e-12
        ) << nu;
    }
}


TEST(segregatedRelaxation, degenerateInputsLeaveTheCorrectorsUnrelaxed)
{
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const double K : {0.0, -1.0, nan, inf})
    {
        EXPECT_EQ(volumetricStiffnessRatio(3.0, K), 0) << K;
    }
    for (const double s : {nan, inf, -inf})
    {
        EXPECT_EQ(volumetricStiffnessRatio(s, 1.0), 0) << s;
    }
    for (const double q : {0.0, -1.0, 1.0, volumetricModeUnstable, nan, inf, -inf})
    {
        EXPECT_EQ(volumetricModeRelaxation(q), 1) << q;
    }
    // Within the margin above q = 2: unchanged; beyond it, the bound
    const double q2 = volumetricModeUnstable;
    EXPECT_EQ(volumetricModeRelaxation(q2*(1 + 1e-9)), 1);
    EXPECT_EQ(volumetricModeRelaxation(q2*(1 + 0.5e-4)), 1);
    const double q = q2*(1 + 2e-4);
    EXPECT_NEAR(volumetricModeRelaxation(q), (1 + volumetricModeBound)/q, 1e-15);
}
