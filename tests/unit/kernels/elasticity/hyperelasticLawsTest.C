// Unit tests of the finite-deformation kernels,
// src/kernels/elasticity/hyperelasticLaws. References: Bonet & Wood (2008)
// and Holzapfel (2000) for the laws; the tangents against central
// differences of the stress; the small-strain limit against hookeLaw;
// objectivity (P(QF) = Q P(F)) and the uniaxial closed form the
// finite-strain patch test uses.

#include "hyperelasticLaws.H"

#include <gtest/gtest.h>
#include <cmath>
#include <functional>

using namespace c4f::elasticity;

namespace
{

Eigen::Matrix3d sampleF()
{
    Eigen::Matrix3d F;
    F << 1.20, -0.15,  0.05,
         0.10,  0.85, -0.20,
        -0.08,  0.12,  0.95;
    return F;
}

Eigen::Matrix3d rotation(const double angle, const Eigen::Vector3d& axis)
{
    return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

Tangent9 centralDifferences
(
    const std::function<Eigen::Matrix3d(const Eigen::Matrix3d&)>& P,
    const Eigen::Matrix3d& F,
    const double h
)
{
    Tangent9 A;
    for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L)
    {
        Eigen::Matrix3d Fp = F, Fm = F;
        Fp(k, L) += h;
        Fm(k, L) -= h;
        const Eigen::Matrix3d dP = (P(Fp) - P(Fm))/(2*h);
        for (int i = 0; i < 3; ++i)
        for (int J = 0; J < 3; ++J)
        {
            A(i + 3*J, k + 3*L) = dP(i, J);
        }
    }
    return A;
}

const Lame rubber = lameFromEngineering(1.0e6, 0.45, false);

//- A general gradient of size ~1e-7, where every law is Hooke's
Eigen::Matrix3d smallGradient()
{
    Eigen::Matrix3d G;
    G << 1.0, -2.0, 3.0, 5.0, 7.0, -1.0, -6.0, 2.0, -4.0;
    return 1e-7*G;
}

} // namespace


TEST(hyperelasticLaws, deformationGradientIsIdentityPlusGradientTransposed)
{
    Eigen::Matrix3d G;
    G << 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9;
    const Eigen::Matrix3d F = deformationGradient(G);
    // F_ij = delta_ij + dD_i/dX_j = delta_ij + G_ji
    EXPECT_DOUBLE_EQ(F(0, 1), G(1, 0));
    EXPECT_DOUBLE_EQ(F(2, 0), G(0, 2));
    EXPECT_DOUBLE_EQ(F(1, 1), 1 + G(1, 1));
}

TEST(hyperelasticLaws, stressFreeAtIdentityAndUnderRigidRotation)
{
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d Q = rotation(0.7, Eigen::Vector3d(1, 2, 3));
    for (const Eigen::Matrix3d& F : {I, Q})
    {
        EXPECT_LT(stVenantKirchhoffPK1(F, rubber).norm(), 1e-9);
        EXPECT_LT(neoHookeanPK1(F, rubber).norm(), 1e-9);
    }
}

TEST(hyperelasticLaws, objectivity)
{
    // P(Q F) = Q P(F) for any rotation Q (frame indifference)
    const Eigen::Matrix3d F = sampleF();
    const Eigen::Matrix3d Q = rotation(1.1, Eigen::Vector3d(-1, 0.5, 2));
    const double scale = neoHookeanPK1(F, rubber).norm();
    EXPECT_LT((neoHookeanPK1(Q*F, rubber) - Q*neoHookeanPK1(F, rubber)).norm(), 1e-12*scale);
    EXPECT_LT
    (
        (stVenantKirchhoffPK1(Q*F, rubber) - Q*stVenantKirchhoffPK1(F, rubber)).norm(),
        1e-12*stVenantKirchhoffPK1(F, rubber).norm()
    );
}

TEST(hyperelasticLaws, cauchyStressIsSymmetric)
{
    const Eigen::Matrix3d F = sampleF();
    for (const Eigen::Matrix3d& P :
         {neoHookeanPK1(F, rubber), stVenantKirchhoffPK1(F, rubber)})
    {
        const Eigen::Matrix3d s = cauchyFromPK1(P, F);
        EXPECT_LT((s - s.transpose()).norm(), 1e-10*s.norm());
    }
}

TEST(hyperelasticLaws, smallStrainLimitIsHooke)
{
    // For |G| ~ 1e-7 both laws give Hooke's sigma to O(|G|^2)
    const Lame p = lameFromEngineering(210e9, 0.3, false);
    const Eigen::Matrix3d G = smallGradient();
    const Eigen::Matrix3d F = deformationGradient(G);
    const Eigen::Matrix3d hooke = stress(G, p);
    const double tol = 1e-5*hooke.norm();
    EXPECT_LT((cauchyFromPK1(neoHookeanPK1(F, p), F) - hooke).norm(), tol);
    EXPECT_LT((cauchyFromPK1(stVenantKirchhoffPK1(F, p), F) - hooke).norm(), tol);
}

TEST(hyperelasticLaws, tangentsMatchCentralDifferences)
{
    for (const Eigen::Matrix3d& F :
         {Eigen::Matrix3d(sampleF()), Eigen::Matrix3d(Eigen::Matrix3d::Identity()),
          Eigen::Matrix3d(0.6*rotation(0.4, Eigen::Vector3d(0, 0, 1)))})
    {
        const double h = 1e-6;
        const Tangent9 nh = neoHookeanTangent(F, rubber);
        const Tangent9 nhFD = centralDifferences
        (
            [](const Eigen::Matrix3d& X) { return neoHookeanPK1(X, rubber); }, F, h
        );
        EXPECT_LT((nh - nhFD).norm(), 1e-6*nh.norm());

        const Tangent9 sv = stVenantKirchhoffTangent(F, rubber);
        const Tangent9 svFD = centralDifferences
        (
            [](const Eigen::Matrix3d& X) { return stVenantKirchhoffPK1(X, rubber); }, F, h
        );
        EXPECT_LT((sv - svFD).norm(), 1e-6*sv.norm());
    }
}

TEST(hyperelasticLaws, tangentAtIdentityIsHookesElasticityTensor)
{
    // dP/dF at F = I equals d sigma/d G^T: Hooke's tangent with the
    // transposition of the gradient convention (major symmetric, so equal)
    const Lame p = lameFromEngineering(70e9, 0.33, false);
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    const Tangent9 hooke = tangent(p);
    EXPECT_LT((neoHookeanTangent(I, p) - hooke).norm(), 1e-9*hooke.norm());
    EXPECT_LT((stVenantKirchhoffTangent(I, p) - hooke).norm(), 1e-9*hooke.norm());
}

TEST(hyperelasticLaws, uniaxialNeoHookeanClosedForm)
{
    // Uniaxial stretch a with free lateral faces: lateral stretch s from
    // a zero lateral Cauchy stress, mu (s^2 - 1) + lambda ln(a s^2) = 0
    // (3D), solved by bisection; then the axial Cauchy stress
    // (mu (a^2 - 1) + lambda ln J)/J with J = a s^2 must match the law
    const double a = 0.8;
    const Lame p = rubber;
    double lo = 0.5, hi = 2.0;
    for (int it = 0; it < 200; ++it)
    {
        const double s = 0.5*(lo + hi);
        const double f = p.mu*(s*s - 1) + p.lambda*std::log(a*s*s);
        (f > 0 ? hi : lo) = s;
    }
    const double s = 0.5*(lo + hi);
    const Eigen::Matrix3d F = Eigen::Vector3d(s, a, s).asDiagonal();
    const Eigen::Matrix3d sig = cauchyFromPK1(neoHookeanPK1(F, p), F);
    const double J = a*s*s;
    const double axial = (p.mu*(a*a - 1) + p.lambda*std::log(J))/J;
    EXPECT_NEAR(sig(0, 0), 0, 1e-9*std::abs(axial));
    EXPECT_NEAR(sig(2, 2), 0, 1e-9*std::abs(axial));
    EXPECT_NEAR(sig(1, 1), axial, 1e-12*std::abs(axial));
    EXPECT_GT(s, 1.0);
}

TEST(hyperelasticLaws, areaRatioIsNansons)
{
    // A stretch s across a face with normal e_x leaves its area; a
    // stretch t along it scales the area by t
    const Eigen::Matrix3d F = Eigen::Vector3d(1.7, 0.8, 1.0).asDiagonal();
    Eigen::Vector3d n;
    EXPECT_NEAR(areaRatio(F, Eigen::Vector3d(1, 0, 0), &n), 0.8, 1e-14);
    EXPECT_NEAR(n(0), 1.0, 1e-14);
    EXPECT_NEAR(areaRatio(F, Eigen::Vector3d(0, 1, 0)), 1.7, 1e-14);
    // A rotation keeps areas and turns the normal
    const Eigen::Matrix3d Q = rotation(0.3, Eigen::Vector3d(0, 0, 1));
    EXPECT_NEAR(areaRatio(Q, Eigen::Vector3d(1, 0, 0), &n), 1.0, 1e-14);
    EXPECT_NEAR(n(1), std::sin(0.3), 1e-14);
}

TEST(hyperelasticLaws, jacobianChecks)
{
    EXPECT_EQ(checkJacobian(sampleF()), JacobianCheck::ok);
    Eigen::Matrix3d inverted = Eigen::Matrix3d::Identity();
    inverted(1, 1) = -0.1;
    EXPECT_EQ(checkJacobian(inverted), JacobianCheck::nonPositive);
    EXPECT_EQ(checkJacobian(Eigen::Matrix3d::Zero()), JacobianCheck::nonPositive);
    Eigen::Matrix3d bad = Eigen::Matrix3d::Identity();
    bad(0, 2) = std::nan("");
    EXPECT_EQ(checkJacobian(bad), JacobianCheck::notFinite);
    EXPECT_NE(describe(JacobianCheck::nonPositive).find("J = det F"), std::string::npos);
}


TEST(hyperelasticLaws, decoupledNeoHookean)
{
    // Stress-free at I and under rotation, objective, Hooke for small G,
    // its tangent against central differences at three F, and Hooke's
    // tangent at I
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d Q = rotation(0.7, Eigen::Vector3d(1, 2, 3));
    EXPECT_LT(decoupledNeoHookeanPK1(I, rubber).norm(), 1e-9);
    EXPECT_LT(decoupledNeoHookeanPK1(Q, rubber).norm(), 1e-9);

    const Eigen::Matrix3d F = sampleF();
    const Eigen::Matrix3d R = rotation(1.1, Eigen::Vector3d(-1, 0.5, 2));
    EXPECT_LT
    (
        (decoupledNeoHookeanPK1(R*F, rubber) - R*decoupledNeoHookeanPK1(F, rubber)).norm(),
        1e-12*decoupledNeoHookeanPK1(F, rubber).norm()
    );

    const Lame p = lameFromEngineering(210e9, 0.3, false);
    const Eigen::Matrix3d G = smallGradient();
    const Eigen::Matrix3d Fs = deformationGradient(G);
    const Eigen::Matrix3d hooke = stress(G, p);
    EXPECT_LT
    (
        (cauchyFromPK1(decoupledNeoHookeanPK1(Fs, p), Fs) - hooke).norm(),
        1e-5*hooke.norm()
    );
    EXPECT_LT((decoupledNeoHookeanTangent(I, p) - tangent(p)).norm(), 1e-9*tangent(p).norm());

    for (const Eigen::Matrix3d& X :
         {Eigen::Matrix3d(sampleF()), Eigen::Matrix3d(I),
          Eigen::Matrix3d(0.6*rotation(0.4, Eigen::Vector3d(0, 0, 1)))})
    {
        const Tangent9 A = decoupledNeoHookeanTangent(X, rubber);
        const Tangent9 AFD = centralDifferences
        (
            [](const Eigen::Matrix3d& Y) { return decoupledNeoHookeanPK1(Y, rubber); },
            X, 1e-6
        );
        EXPECT_LT((A - AFD).norm(), 1e-6*A.norm());
    }
}


TEST(hyperelasticLaws, decoupledNeoHookeanStiffensInCompression)
{
    // Under uniaxial compression to 0.8 with free lateral faces (3D) the
    // decoupled law gives more axial stress than the Simo form: about
    // 6 % at nu 0.3 (the two differ in the volumetric part)
    const Lame p = lameFromEngineering(1.0e6, 0.3, false);
    const double a = 0.8;
    const auto axial = [&](auto PK1)
    {
        // bisection on the lateral stretch s for a zero lateral Cauchy stress
        double lo = 0.9, hi = 1.5;
        Eigen::Matrix3d F;
        for (int it = 0; it < 200; ++it)
        {
            const double s = 0.5*(lo + hi);
            F = Eigen::Vector3d(s, s, a).asDiagonal();
            const double sxx = cauchyFromPK1(PK1(F, p), F)(0, 0);
            (sxx > 0 ? hi : lo) = s;
        }
        return cauchyFromPK1(PK1(F, p), F)(2, 2);
    };
    const double simo = axial([](const Eigen::Matrix3d& F, const Lame& q)
                              { return neoHookeanPK1(F, q); });
    const double dec = axial([](const Eigen::Matrix3d& F, const Lame& q)
                             { return decoupledNeoHookeanPK1(F, q); });
    EXPECT_LT(simo, 0);
    EXPECT_GT(dec/simo - 1, 0.03);
    EXPECT_LT(dec/simo - 1, 0.09);
}
