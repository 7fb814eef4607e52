// Unit tests of the rigid-body motion of a contact tool, src/kernels/
// rigid/rigidMotion: Q is a rotation (orthogonal, det 1) for any rotation
// vector, exactly I for a zero one, the inverse undoes the motion, and
// the motion is Eigen's own translation * rotation about the centre.

#include "rigidMotion.H"
#include "analyticSurface.H"
#include "../fpeTraps.H"

#include <gtest/gtest.h>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

using namespace c4f::rigid;
using V = Eigen::Vector3d;
using M = Eigen::Matrix3d;

namespace
{

constexpr double eps = std::numeric_limits<double>::epsilon();
const double pi = std::acos(-1.0);

V randomVector(std::mt19937& gen, const double scale)
{
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    return scale*V(U(gen), U(gen), U(gen));
}

// Rotation vectors from 1e-170 to 1e3 rad in size (many turns), and the
// special angles pi and 2 pi
std::vector<V> rotationVectors(std::mt19937& gen)
{
    std::vector<V> th;
    std::uniform_real_distribution<double> U(0.0, 1.0);
    for (int i = 0; i < 200; ++i)
    {
        const V axis = randomVector(gen, 1.0).normalized();
        th.push_back(std::pow(10.0, -10 + 13*U(gen))*axis);
    }
    for (const double a : {1e-170, 1e-20, 1e-8, pi, 2*pi, 1e6})
    {
        th.push_back(a*randomVector(gen, 1.0).normalized());
    }
    return th;
}

} // End anonymous namespace


TEST(rigidMotion, identityAndZeroRotationAreExact)
{
    const RigidMotion I;
    EXPECT_EQ(I.rotation(), M::Identity());
    const V X(0.3, -7.0, 1e6);
    EXPECT_EQ(I.apply(X), X);
    EXPECT_EQ(I.applyInverse(X), X);
    EXPECT_EQ(I.displacement(X), V::Zero());
    EXPECT_EQ(I.rotateVector(X), X);

    // theta = 0 (and -0): Q exactly I, whatever u and c
    for (const V& zero : {V(0, 0, 0), V(-0.0, 0.0, -0.0)})
    {
        const V u(1e-3, 2, -3), c(5, -6, 7);
        const RigidMotion m(u, zero, c);
        EXPECT_EQ(m.rotation(), M::Identity());
        EXPECT_EQ(m.rotateVector(X), X);
        EXPECT_EQ(m.displacement(X), u);
        EXPECT_NEAR((m.apply(X) - (X + u)).norm(), 0, 4*eps*X.norm());
    }
}


TEST(rigidMotion, rotationIsOrthogonalWithUnitDeterminant)
{
    const FpeTraps traps(FE_OVERFLOW | FE_DIVBYZERO | FE_INVALID);
    std::mt19937 gen(3);
    double maxOrth = 0, maxDet = 0;
    for (const V& th : rotationVectors(gen))
    {
        const RigidMotion m(randomVector(gen, 10), th, randomVector(gen, 10));
        const M& Q = m.rotation();
        ASSERT_TRUE(Q.allFinite()) << th.transpose();
        maxOrth = std::max(maxOrth, (Q.transpose()*Q - M::Identity()).norm());
        maxDet = std::max(maxDet, std::abs(Q.determinant() - 1));
        // The axis is fixed by the rotation
        const double angle = th.norm();
        if (angle > 0)
        {
            const V axis = th/angle;
            EXPECT_NEAR((Q*axis - axis).norm(), 0, 8*eps) << th.transpose();
        }
    }
    EXPECT_LT(maxOrth, 8*eps);
    EXPECT_LT(maxDet, 8*eps);
}


TEST(rigidMotion, roundTripThroughTheInverse)
{
    const FpeTraps traps(FE_OVERFLOW | FE_DIVBYZERO | FE_INVALID);
    std::mt19937 gen(5);
    for (const double scale : {1e-6, 1.0, 1e6})
    {
        for (const V& th : rotationVectors(gen))
        {
            const RigidMotion m(randomVector(gen, scale), th, randomVector(gen, scale));
            for (int i = 0; i < 5; ++i)
            {
                const V X = randomVector(gen, scale);
                const double tol = 32*eps*scale;
                EXPECT_NEAR((m.applyInverse(m.apply(X)) - X).norm(), 0, tol);
                EXPECT_NEAR((m.apply(m.applyInverse(X)) - X).norm(), 0, tol);
                EXPECT_NEAR((m.displacement(X) - (m.apply(X) - X)).norm(), 0, tol);
                // Rigid: distances and lengths are kept
                const V Y = randomVector(gen, scale);
                EXPECT_NEAR((m.apply(X) - m.apply(Y)).norm(), (X - Y).norm(), tol);
                EXPECT_NEAR(m.rotateVector(X).norm(), X.norm(), tol);
            }
        }
    }
}


TEST(rigidMotion, halfTurnAboutAnAxis)
{
    // Q = 2 e e^T - I: the axis is kept, everything across it reversed
    for (const V& axis : {V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), V(1, 1, 1), V(-0.4, 0.5, 2.0)})
    {
        const V e = axis.normalized();
        const RigidMotion m(V::Zero(), pi*e, V::Zero());
        const M expected = 2*e*e.transpose() - M::Identity();
        EXPECT_NEAR((m.rotation() - expected).norm(), 0, 8*eps) << axis.transpose();

        // About a centre off the origin, with a translation: the centre
        // moves by u, a point across the axis at c + r lands at c + u - r
        const V c(1, -2, 3), u(0.5, 0.25, -1);
        const RigidMotion mc(u, pi*e, c);
        const V r = V(0.3, 0.7, -0.2) - V(0.3, 0.7, -0.2).dot(e)*e;
        EXPECT_NEAR((mc.apply(c + r) - (c + u - r)).norm(), 0, 16*eps);
        EXPECT_NEAR((mc.apply(c + 2*e) - (c + u + 2*e)).norm(), 0, 16*eps);
    }
    // A quarter turn about z takes x to y
    const RigidMotion q(V::Zero(), V(0, 0, pi/2), V::Zero());
    EXPECT_NEAR((q.rotateVector(V(1, 0, 0)) - V(0, 1, 0)).norm(), 0, 4*eps);
}


TEST(rigidMotion, centreMovesByTheTranslation)
{
    std::mt19937 gen(9);
    for (const V& th : rotationVectors(gen))
    {
        const V u = randomVector(gen, 2.0), c = randomVector(gen, 1e3);
        const RigidMotion m(u, th, c);
        // Exactly: the rotation acts on c - c = 0
        EXPECT_EQ(m.displacement(c), u);
        EXPECT_NEAR((m.apply(c) - (c + u)).norm(), 0, 4*eps*c.norm());
    }
}


TEST(rigidMotion, agreesWithEigenTransformComposition)
{
    std::mt19937 gen(13);
    for (const V& th : rotationVectors(gen))
    {
        const V u = randomVector(gen, 2.0), c = randomVector(gen, 3.0);
        const RigidMotion m(u, th, c);

        const double angle = th.norm();
        const Eigen::AngleAxisd aa(angle, angle > 0 ? V(th/angle) : V::UnitX());
        // The angle's own rounding, an ulp of |theta| (the kernel's norm is
        // scaled, Eigen's is not), turns Q by up to eps |theta|
        const double tol = 16*eps*(1 + angle);
        EXPECT_NEAR((m.rotation() - aa.toRotationMatrix()).norm(), 0, tol);

        // x = T(c + u) R T(-c) X, built by Eigen's own Transform algebra
        const Eigen::Affine3d T =
            Eigen::Translation3d(c + u)*aa*Eigen::Translation3d(-c);
        for (int i = 0; i < 5; ++i)
        {
            const V X = randomVector(gen, 5.0);
            EXPECT_NEAR((m.apply(X) - T*X).norm(), 0, 10*tol);
            EXPECT_NEAR((m.applyInverse(T*X) - X).norm(), 0, 10*tol);
            EXPECT_NEAR((m.rotateVector(X) - aa*X).norm(), 0, 10*tol);
        }
    }

    // Coaxial rotation vectors add: Q(a e) Q(b e) = Q((a + b) e)
    const V e = V(0.2, -0.9, 0.4).normalized();
    const RigidMotion A(V::Zero(), 0.7*e, V::Zero()), B(V::Zero(), -2.1*e, V::Zero());
    const RigidMotion AB(V::Zero(), -1.4*e, V::Zero());
    EXPECT_NEAR((A.rotation()*B.rotation() - AB.rotation()).norm(), 0, 8*eps);

    // Small angles: Q = I + skew(theta) + O(|theta|^2)
    const V th(1e-8, -2e-8, 3e-8);
    M K;
    K << 0, -th(2), th(1),
         th(2), 0, -th(0),
         -th(1), th(0), 0;
    const RigidMotion s(V::Zero(), th, V::Zero());
    EXPECT_NEAR((s.rotation() - (M::Identity() + K)).norm(), 0, th.squaredNorm() + 4*eps);
}


TEST(rigidMotion, movedSurfaceKeepsTheGap)
{
    // A tool surface given in the reference configuration: the gap of a
    // current point is that of its reference point (applyInverse), and the
    // moved plane (apply p0, rotateVector n) gives the same gap
    std::mt19937 gen(17);
    const V p0(0.1, 0.2, 0.3), n = V(1, -1, 2).normalized();
    for (const V& th : rotationVectors(gen))
    {
        const RigidMotion m(randomVector(gen, 2.0), th, randomVector(gen, 1.0));
        const V x = randomVector(gen, 3.0);
        const SurfacePoint ref = closestOnPlane(m.applyInverse(x), p0, n);
        const SurfacePoint cur = closestOnPlane(x, m.apply(p0), m.rotateVector(n));
        EXPECT_NEAR(ref.gap, cur.gap, 64*eps);
        EXPECT_NEAR((m.apply(ref.point) - cur.point).norm(), 0, 64*eps);
        EXPECT_NEAR((m.rotateVector(ref.normal) - cur.normal).norm(), 0, 8*eps);
    }
}


TEST(rigidMotion, nonFiniteInputThrows)
{
    const double NaN = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const V z = V::Zero(), bad1(NaN, 0, 0), bad2(0, 0, -inf);
    for (const V& bad : {bad1, bad2})
    {
        EXPECT_THROW(RigidMotion(bad, z, z), std::invalid_argument);
        EXPECT_THROW(RigidMotion(z, bad, z), std::invalid_argument);
        EXPECT_THROW(RigidMotion(z, z, bad), std::invalid_argument);
    }
}
