// Unit tests of the pure Coulomb friction kernel,
// src/kernels/contact/coulombReturnMap.
// References: Wriggers, Computational Contact Mechanics (2nd ed. 2006),
// sec. 5.2 and Laursen & Simo (1993) for the return map; the consistent
// tangent is checked against central differences of the traction itself;
// the degenerate sweep follows the spirit of ipc-toolkit's friction tests
// (every combination of zero, tiny and large inputs must stay finite).

#include "coulombReturnMap.H"

#include <gtest/gtest.h>
#include <cmath>
#include <limits>

using namespace c4f::contact;

namespace
{

// A normal that is not aligned with any axis, so that no projection
// component is trivially zero
Eigen::Vector3d tiltedNormal()
{
    return Eigen::Vector3d(1, -2, 2).normalized();
}

Eigen::Matrix3d projector(const Eigen::Vector3d& n)
{
    return Eigen::Matrix3d::Identity() - n*n.transpose();
}

// Max-abs error of the tangent against central differences, relative to
// the largest tangent entry
double tangentError
(
    const Eigen::Vector3d& n,
    const Eigen::Vector3d& tTold,
    const Eigen::Vector3d& xi,
    const double pN,
    const double mu,
    const double epsT,
    const double h
)
{
    const Eigen::Matrix3d K = coulombReturnMap(n, tTold, xi, pN, mu, epsT).tangent;
    double maxErr = 0;
    for (int b = 0; b < 3; ++b)
    {
        Eigen::Vector3d dxi = Eigen::Vector3d::Zero();
        dxi(b) = h;
        const Eigen::Vector3d dt =
            (
                coulombReturnMap(n, tTold, xi + dxi, pN, mu, epsT).traction
              - coulombReturnMap(n, tTold, xi - dxi, pN, mu, epsT).traction
            )/(2*h);
        for (int a = 0; a < 3; ++a)
        {
            maxErr = std::max(maxErr, std::abs(dt(a) - K(a, b)));
        }
    }
    return maxErr/K.cwiseAbs().maxCoeff();
}

} // namespace


TEST(coulombReturnMap, slipIncrementRemovesNormalPart)
{
    const Eigen::Vector3d n = tiltedNormal();
    const Eigen::Vector3d dS(3e-3, 1e-3, -2e-3), dM(-1e-3, 4e-3, 5e-4);
    const Eigen::Vector3d xi = slipIncrement(n, dS, dM);
    EXPECT_NEAR(n.dot(xi), 0, 1e-18);

    // The tangential part of the relative increment survives unchanged
    const Eigen::Vector3d d = dS - dM;
    EXPECT_LT((xi - (d - n.dot(d)*n)).norm(), 1e-18);
    EXPECT_GT(xi.norm(), 1e-3);

    // A purely normal approach is no slip at all
    EXPECT_LT(slipIncrement(n, 2e-3*n, -1e-3*n).norm(), 1e-18);

    // Exact case: n = e_z drops the z component and nothing else
    const Eigen::Vector3d e =
        slipIncrement(Eigen::Vector3d::UnitZ(), {0.5, -0.25, 3}, {0.25, 0.5, -1});
    EXPECT_EQ(e(0), 0.25);
    EXPECT_EQ(e(1), -0.75);
    EXPECT_EQ(e(2), 0.0);
}

TEST(coulombReturnMap, slipIncrementIsLinearAndIgnoresRigidTranslation)
{
    const Eigen::Vector3d n = tiltedNormal();
    const Eigen::Vector3d s1(1, 2, 3), m1(-1, 0.5, 2), s2(0.3, -4, 1), m2(2, 2, -2);
    const double a = 2.5, b = -0.75;
    const Eigen::Vector3d lhs = slipIncrement(n, a*s1 + b*s2, a*m1 + b*m2);
    const Eigen::Vector3d rhs = a*slipIncrement(n, s1, m1) + b*slipIncrement(n, s2, m2);
    EXPECT_LT((lhs - rhs).norm(), 1e-14*rhs.norm());

    // Slave and master moving together do not slip
    const Eigen::Vector3d c(7, -3, 11);
    EXPECT_LT((slipIncrement(n, s1 + c, m1 + c) - slipIncrement(n, s1, m1)).norm(), 1e-13);
}

TEST(coulombReturnMap, stickReturnsTrialTractionExactly)
{
    // n = e_z with binary-exact inputs: t_tr = (2 - 100*0.01, -1 + 100*0.005, 0)
    // = (1, -0.5, 0), |t_tr| = 1.118 < mu pN = 0.5*4 = 2
    const CoulombResult r = coulombReturnMap
    (
        Eigen::Vector3d::UnitZ(), {2, -1, 0}, {0.01, -0.005, 0}, 4, 0.5, 100
    );
    EXPECT_FALSE(r.slip);
    EXPECT_EQ(r.slipIncrementMagnitude, 0.0);
    EXPECT_DOUBLE_EQ(r.traction(0), 1.0);
    EXPECT_DOUBLE_EQ(r.traction(1), -0.5);
    EXPECT_EQ(r.traction(2), 0.0);

    // Tilted normal: t = P tTold - eps_T xi for a tangential xi
    const Eigen::Vector3d n = tiltedNormal();
    const Eigen::Matrix3d P = projector(n);
    const Eigen::Vector3d tTold = P*Eigen::Vector3d(10, 20, -5);
    const Eigen::Vector3d xi = P*Eigen::Vector3d(1e-5, -3e-5, 2e-5);
    const double epsT = 1e6;
    const Eigen::Vector3d tTr = tTold - epsT*xi;
    const double pN = 1e3, mu = 0.3;
    ASSERT_LT(tTr.norm(), 0.5*mu*pN);
    const CoulombResult s = coulombReturnMap(n, tTold, xi, pN, mu, epsT);
    EXPECT_FALSE(s.slip);
    EXPECT_LT((s.traction - tTr).norm(), 1e-13*tTr.norm());
    EXPECT_LT((s.tangent + epsT*P).norm(), 1e-12*epsT);
}

TEST(coulombReturnMap, slipReturnsToTheCoulombCone)
{
    const Eigen::Vector3d n = tiltedNormal();
    const Eigen::Matrix3d P = projector(n);
    const Eigen::Vector3d tTold = P*Eigen::Vector3d(50, -20, 30);
    const Eigen::Vector3d xi = P*Eigen::Vector3d(-2e-4, 1e-4, 3e-4);
    const double pN = 200, mu = 0.4, epsT = 1e6;
    const Eigen::Vector3d tTr = tTold - epsT*xi;
    ASSERT_GT(tTr.norm(), 2*mu*pN);

    const CoulombResult r = coulombReturnMap(n, tTold, xi, pN, mu, epsT);
    EXPECT_TRUE(r.slip);
    EXPECT_NEAR(r.traction.norm(), mu*pN, 1e-12*mu*pN);

    // The trial and the bound it was judged against, as the glue sees them
    EXPECT_LT((r.trial - tTr).norm(), 1e-12*tTr.norm());
    EXPECT_EQ(r.bound, mu*pN);

    // Radial return: parallel to the trial and pointing the same way
    EXPECT_LT(r.traction.cross(tTr).norm(), 1e-12*r.traction.norm()*tTr.norm());
    EXPECT_GT(r.traction.dot(tTr), 0);

    const double gamma = (tTr.norm() - mu*pN)/epsT;
    EXPECT_NEAR(r.slipIncrementMagnitude, gamma, 1e-12*gamma);

    // The multiplier is the one of t_T = t_tr - eps_T gamma m
    const Eigen::Vector3d m = tTr.normalized();
    EXPECT_LT((r.traction - (tTr - epsT*r.slipIncrementMagnitude*m)).norm(), 1e-9*mu*pN);
}

TEST(coulombReturnMap, frictionOpposesSlipFromRest)
{
    // No stored traction: the friction force points against the slip
    // and dissipates, t_T.xi = -mu pN |xi| < 0
    const Eigen::Vector3d n = tiltedNormal();
    const Eigen::Vector3d xi = projector(n)*Eigen::Vector3d(1e-3, 2e-3, 0);
    const double pN = 10, mu = 0.3, epsT = 1e8;
    const CoulombResult r =
        coulombReturnMap(n, Eigen::Vector3d::Zero(), xi, pN, mu, epsT);
    ASSERT_TRUE(r.slip);
    EXPECT_NEAR(r.traction.dot(xi), -mu*pN*xi.norm(), 1e-12*mu*pN*xi.norm());
}

TEST(coulombReturnMap, tractionIsTangentialEvenForRotatedNormal)
{
    // tTold was stored for another normal (e_z) and is not tangential to n;
    // xi deliberately has a normal part too
    const Eigen::Vector3d n = tiltedNormal();
    const Eigen::Vector3d tTold(30, -40, 0);
    ASSERT_GT(std::abs(n.dot(tTold)), 10.0);
    const Eigen::Vector3d xi(1e-6, 2e-6, -3e-6);
    ASSERT_GT(std::abs(n.dot(xi)), 1e-6);

    for (const double pN : {1e3, 1.0})  // stick, then slip
    {
        const CoulombResult r = coulombReturnMap(n, tTold, xi, pN, 0.5, 1e6);
        EXPECT_EQ(r.slip, pN < 10);
        EXPECT_NEAR(n.dot(r.traction), 0, 1e-13*tTold.norm());
        EXPECT_GT(r.traction.norm(), 0.1);
        // The tangent maps every increment into the tangent plane too
        EXPECT_LT((n.transpose()*r.tangent).norm(), 1e-10*r.tangent.norm());
    }
}

TEST(coulombReturnMap, stickTangentMatchesCentralDifferences)
{
    const Eigen::Vector3d n = tiltedNormal();
    const Eigen::Vector3d tTold = projector(n)*Eigen::Vector3d(10, -5, 2);
    const Eigen::Vector3d xi = projector(n)*Eigen::Vector3d(2e-6, 1e-6, -1e-6);
    const double pN = 1e3, mu = 0.3, epsT = 1e6;
    const CoulombResult r = coulombReturnMap(n, tTold, xi, pN, mu, epsT);
    ASSERT_FALSE(r.slip);
    // Well inside the cone, so no difference stencil crosses into slip
    ASSERT_LT(r.traction.norm(), 0.2*mu*pN);
    EXPECT_LT(tangentError(n, tTold, xi, pN, mu, epsT, 1e-6*xi.norm()), 1e-6);
}

TEST(coulombReturnMap, slipTangentMatchesCentralDifferences)
{
    const Eigen::Vector3d n = tiltedNormal();
    const Eigen::Vector3d tTold = projector(n)*Eigen::Vector3d(10, -5, 2);
    const Eigen::Vector3d xi = projector(n)*Eigen::Vector3d(-1e-3, 2e-3, 5e-4);
    const double pN = 100, mu = 0.3, epsT = 1e5;
    const CoulombResult r = coulombReturnMap(n, tTold, xi, pN, mu, epsT);
    ASSERT_TRUE(r.slip);
    // Far outside the cone (|t_tr| ~ 7 mu pN), so every stencil point slips
    ASSERT_GT((tTold - epsT*xi).norm(), 5*mu*pN);
    EXPECT_LT(tangentError(n, tTold, xi, pN, mu, epsT, 1e-6*xi.norm()), 1e-6);

    // The slip tangent has no stiffness along the slip direction m
    const Eigen::Vector3d m = r.traction.normalized();
    EXPECT_LT((r.tangent*m).norm(), 1e-10*r.tangent.norm());
}

TEST(coulombReturnMap, tangentMatchesCentralDifferencesWithNormalIncrement)
{
    // The projected trial makes -eps_T P and the slip tangent exact for
    // an arbitrary xi, not only for a tangential one
    const Eigen::Vector3d n = tiltedNormal();
    const Eigen::Vector3d tTold(10, -5, 2);
    const double mu = 0.3, epsT = 1e5;
    const Eigen::Vector3d xiStick(1e-6, -2e-6, 4e-6), xiSlip(-1e-3, 2e-3, 5e-4);
    ASSERT_FALSE(coulombReturnMap(n, tTold, xiStick, 1e3, mu, epsT).slip);
    ASSERT_TRUE(coulombReturnMap(n, tTold, xiSlip, 100, mu, epsT).slip);
    EXPECT_LT(tangentError(n, tTold, xiStick, 1e3, mu, epsT, 1e-6*xiStick.norm()), 1e-6);
    EXPECT_LT(tangentError(n, tTold, xiSlip, 100, mu, epsT, 1e-6*xiSlip.norm()), 1e-6);
}

TEST(coulombReturnMap, tractionIsContinuousAcrossTheSlipBoundary)
{
    // Scaling xi so that |t_tr| passes through mu pN must not make t_T jump
    const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d xi(3e-6, 4e-6, 0);  // |xi| = 5e-6
    const double pN = 10, mu = 0.5, epsT = 1e6; // boundary at scale 1
    const CoulombResult below = coulombReturnMap(n, Eigen::Vector3d::Zero(), (1 - 1e-9)*xi, pN, mu, epsT);
    const CoulombResult above = coulombReturnMap(n, Eigen::Vector3d::Zero(), (1 + 1e-9)*xi, pN, mu, epsT);
    EXPECT_FALSE(below.slip);
    EXPECT_TRUE(above.slip);
    EXPECT_LT((below.traction - above.traction).norm(), 1e-8*mu*pN);
    EXPECT_LT(above.slipIncrementMagnitude, 1e-14);
}

TEST(coulombReturnMap, noContactGivesZeroTractionAndTangent)
{
    const Eigen::Vector3d n = tiltedNormal();
    const Eigen::Vector3d tTold = projector(n)*Eigen::Vector3d(5, 1, 0);
    const Eigen::Vector3d xi = projector(n)*Eigen::Vector3d(1e-4, 0, 1e-4);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const double pN : {0.0, -1.0, -1e300, nan})
    {
        const CoulombResult r = coulombReturnMap(n, tTold, xi, pN, 0.3, 1e6);
        EXPECT_EQ(r.traction.norm(), 0.0) << "pN = " << pN;
        EXPECT_EQ(r.tangent.norm(), 0.0) << "pN = " << pN;
        EXPECT_TRUE(r.slip);
        const double expected = (tTold - 1e6*xi).norm()/1e6;
        EXPECT_NEAR(r.slipIncrementMagnitude, expected, 1e-12*expected);
    }

    // Nothing to slip against and nothing stored: stick at rest
    const CoulombResult z =
        coulombReturnMap(n, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0, 0.3, 1e6);
    EXPECT_FALSE(z.slip);
    EXPECT_EQ(z.slipIncrementMagnitude, 0.0);
    EXPECT_EQ(z.traction.norm(), 0.0);
}

TEST(coulombReturnMap, frictionlessGivesZeroTraction)
{
    const Eigen::Vector3d n = tiltedNormal();
    const Eigen::Vector3d xi = projector(n)*Eigen::Vector3d(1e-4, 2e-4, 0);
    const CoulombResult r = coulombReturnMap(n, Eigen::Vector3d::Zero(), xi, 1e3, 0.0, 1e6);
    EXPECT_EQ(r.traction.norm(), 0.0);
    EXPECT_EQ(r.tangent.norm(), 0.0);
    EXPECT_TRUE(r.slip);
    EXPECT_NEAR(r.slipIncrementMagnitude, xi.norm(), 1e-12*xi.norm());
}

TEST(coulombReturnMap, zeroTrialTractionIsStick)
{
    // |t_tr| == 0 exactly with an open cone: stick, no division by zero
    const Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
    const CoulombResult r = coulombReturnMap
    (
        n, Eigen::Vector3d(0, 0, 7), Eigen::Vector3d(0, 0, 1e-3), 10, 0.3, 1e6
    );
    EXPECT_FALSE(r.slip);
    EXPECT_EQ(r.traction.norm(), 0.0);
    EXPECT_EQ(r.slipIncrementMagnitude, 0.0);
    EXPECT_LT((r.tangent + 1e6*projector(n)).norm(), 1e-9);
}

TEST(coulombReturnMap, degenerateSweepStaysFiniteAndInsideTheCone)
{
    const Eigen::Vector3d normals[] =
    {
        Eigen::Vector3d::UnitX(),
        tiltedNormal(),
        Eigen::Vector3d(1, 1e-9, 0).normalized()
    };
    const Eigen::Vector3d directions[] =
    {
        {1, 0, 0}, {0, 1, 0}, {0.3, -0.7, 0.2}, {1e-10, 1, -1}
    };
    const Eigen::Vector3d oldTractions[] =
    {
        Eigen::Vector3d::Zero(), {1, -2, 3}, {1e3, 0, -1e3}
    };

    int checked = 0, slipped = 0, stuck = 0;
    for (const auto& n : normals)
    for (const auto& d : directions)
    for (const auto& tTold : oldTractions)
    for (const double scale : {0.0, 1e-300, 1e-12, 1e-6, 1.0, 1e3})
    for (const double pN : {0.0, 1e-12, 1.0, 1e3})
    for (const double mu : {0.0, 0.3})
    for (const double epsT : {1.0, 1e9})
    {
        const Eigen::Vector3d xi = slipIncrement(n, scale*d, Eigen::Vector3d::Zero());
        const CoulombResult r = coulombReturnMap(n, tTold, xi, pN, mu, epsT);
        ASSERT_TRUE(r.traction.allFinite())
            << "pN " << pN << " mu " << mu << " scale " << scale;
        ASSERT_TRUE(r.tangent.allFinite())
            << "pN " << pN << " mu " << mu << " scale " << scale;
        ASSERT_TRUE(std::isfinite(r.slipIncrementMagnitude));
        EXPECT_GE(r.slipIncrementMagnitude, 0.0);
        EXPECT_LE(r.traction.norm(), mu*pN*(1 + 1e-12))
            << "pN " << pN << " mu " << mu << " scale " << scale;
        EXPECT_LT(std::abs(n.dot(r.traction)), 1e-12*(1 + r.traction.norm()));
        ++checked;
        r.slip ? ++slipped : ++stuck;
    }
    // The sweep must exercise both branches, not only the degenerate ones
    EXPECT_EQ(checked, 3*4*3*6*4*2*2);
    EXPECT_GT(slipped, 100);
    EXPECT_GT(stuck, 100);
}

TEST(coulombReturnMap, frictionParameterChecks)
{
    EXPECT_EQ(checkFrictionParameters(0.3, 1e6), FrictionCheck::ok);
    EXPECT_EQ(checkFrictionParameters(0.0, 1e6), FrictionCheck::ok);
    EXPECT_EQ(checkFrictionParameters(-0.1, 1e6), FrictionCheck::negativeMu);
    EXPECT_EQ(checkFrictionParameters(0.3, 0.0), FrictionCheck::nonPositiveEpsT);
    EXPECT_EQ(checkFrictionParameters(0.3, -1e6), FrictionCheck::nonPositiveEpsT);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(checkFrictionParameters(nan, 1e6), FrictionCheck::negativeMu);
    EXPECT_EQ(checkFrictionParameters(0.3, nan), FrictionCheck::nonPositiveEpsT);
    EXPECT_EQ(checkFrictionParameters(-inf, 1e6), FrictionCheck::negativeMu);
    EXPECT_NE(describe(FrictionCheck::negativeMu).find("mu >= 0"), std::string::npos);
    EXPECT_NE(describe(FrictionCheck::nonPositiveEpsT).find("eps_T > 0"), std::string::npos);
    EXPECT_EQ(describe(FrictionCheck::ok), "valid");
}
