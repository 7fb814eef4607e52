// Unit tests of the analytic rigid surfaces, src/kernels/rigid/
// analyticSurface: the gap is the signed distance (its gradient by central
// differences is the normal), the point is on the surface and the gap is
// measured along the normal from it; no NaN on a centre or an axis, next
// to the surface, at 1e6 m or with a 1e-9 m radius, with OpenFOAM's
// floating-point traps on.

#include "analyticSurface.H"
#include "../fpeTraps.H"

#include <gtest/gtest.h>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using namespace c4f::rigid;
using V = Eigen::Vector3d;

namespace
{

constexpr double eps = std::numeric_limits<double>::epsilon();

// One surface under test: its projection and its exact geometry (the
// distance of a point of the surface from its centre, axis or plane, which
// must be R, or 0 for the plane)
struct Case
{
    std::string name;
    std::function<SurfacePoint(const V&)> project;
    std::function<double(const V&)> offSurface;
    V centre;
    double R;
};

std::vector<Case> cases(const V& o, const double R)
{
    const V n = V(0.3, -1.2, 0.7);
    const V e = V(-0.4, 0.5, 2.0);
    const V t = e.normalized();
    std::vector<Case> cs;
    cs.push_back
    ({
        "plane",
        [=](const V& x) { return closestOnPlane(x, o, n); },
        [=](const V& y) { return std::abs((y - o).dot(n.normalized())); },
        o, R
    });
    for (const bool inside : {false, true})
    {
        const std::string side = inside ? " inside" : " outside";
        cs.push_back
        ({
            "sphere" + side,
            [=](const V& x) { return closestOnSphere(x, o, R, inside); },
            [=](const V& y) { return std::abs((y - o).norm() - R); },
            o, R
        });
        cs.push_back
        ({
            "cylinder" + side,
            [=](const V& x) { return closestOnCylinder(x, o, e, R, inside); },
            [=](const V& y)
            {
                const V d = y - o;
                return std::abs((d - d.dot(t)*t).norm() - R);
            },
            o, R
        });
    }
    return cs;
}

// The properties every projection has: finite, unit normal, point on the
// surface, gap along the normal from it, x = point + gap normal (x - point
// is parallel to the normal: the closest point). tol is the rounding of
// the coordinates involved.
void expectConsistent(const Case& c, const V& x, const SurfacePoint& p, const double tol)
{
    ASSERT_TRUE(p.point.allFinite()) << c.name;
    ASSERT_TRUE(p.normal.allFinite()) << c.name;
    ASSERT_TRUE(std::isfinite(p.gap)) << c.name;
    EXPECT_NEAR(p.normal.norm(), 1.0, 4*eps) << c.name;
    EXPECT_NEAR(c.offSurface(p.point), 0.0, tol) << c.name << " x = " << x.transpose();
    EXPECT_NEAR((x - p.point).dot(p.normal), p.gap, tol) << c.name;
    EXPECT_NEAR((p.point + p.gap*p.normal - x).norm(), 0.0, tol) << c.name;
}

// A random unit vector, and a point at distance `dist` from the centre
// (sphere), axis (cylinder) or plane along it, moved along the axis or
// the plane as well
V randomUnit(std::mt19937& gen)
{
    std::normal_distribution<double> N(0.0, 1.0);
    V v(N(gen), N(gen), N(gen));
    return v.normalized();
}

} // End anonymous namespace


TEST(analyticSurface, knownValues)
{
    const SurfacePoint pl = closestOnPlane(V(1, 2, 3), V(0, 0, 1), V(0, 0, 2));
    EXPECT_EQ(pl.normal, V(0, 0, 1));
    EXPECT_EQ(pl.gap, 2.0);
    EXPECT_EQ(pl.point, V(1, 2, 1));
    EXPECT_TRUE(pl.valid);

    const SurfacePoint so = closestOnSphere(V(3, 0, 0), V(0, 0, 0), 1.0);
    EXPECT_EQ(so.gap, 2.0);
    EXPECT_EQ(so.normal, V(1, 0, 0));
    EXPECT_EQ(so.point, V(1, 0, 0));
    EXPECT_TRUE(so.valid);
    const SurfacePoint si = closestOnSphere(V(3, 0, 0), V(0, 0, 0), 1.0, true);
    EXPECT_EQ(si.gap, -2.0);
    EXPECT_EQ(si.normal, V(-1, 0, 0));
    EXPECT_EQ(si.point, V(1, 0, 0));
    // A ball in a cavity of radius 1, 0.25 from its centre: 0.75 open
    EXPECT_EQ(closestOnSphere(V(0, 0, 0.25), V(0, 0, 0), 1.0, true).gap, 0.75);

    const SurfacePoint co = closestOnCylinder(V(0, 5, 7), V(0, 0, 1), V(0, 0, -3), 2.0);
    EXPECT_EQ(co.gap, 3.0);
    EXPECT_EQ(co.normal, V(0, 1, 0));
    EXPECT_EQ(co.point, V(0, 2, 7));
    const SurfacePoint ci = closestOnCylinder(V(0, 1.5, 7), V(0, 0, 1), V(0, 0, 1), 2.0, true);
    EXPECT_EQ(ci.gap, 0.5);
    EXPECT_EQ(ci.normal, V(0, -1, 0));
    EXPECT_EQ(ci.point, V(0, 2, 7));
}


TEST(analyticSurface, gapGradientIsTheNormalByCentralDifferences)
{
    std::mt19937 gen(20240611);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    const V o(0.3, -0.7, 1.1);
    const double R = 0.8;

    for (const Case& c : cases(o, R))
    {
        double maxErr = 0;
        int n = 0;
        for (int i = 0; i < 400; ++i)
        {
            // Distances from the centre/axis/plane 0.05 R .. 100 R, half of
            // them within 1e-9 .. 1e-1 R of the surface on either side
            double dist;
            if (i % 2 == 0)
            {
                dist = R*std::pow(10.0, -1.3 + 3.3*0.5*(U(gen) + 1));
            }
            else
            {
                dist = R*(1 + (U(gen) > 0 ? 1 : -1)*std::pow(10.0, -9 + 8*0.5*(U(gen) + 1)));
            }
            V x;
            if (c.name == "plane")
            {
                // Signed distances either side, over any point of the plane
                const V nn = V(0.3, -1.2, 0.7).normalized();
                const V along = randomUnit(gen);
                const V inPlane = 5*(along - along.dot(nn)*nn);
                x = o + inPlane + (U(gen) > 0 ? 1 : -1)*dist*nn;
            }
            else if (c.name.rfind("sphere", 0) == 0)
            {
                x = o + dist*randomUnit(gen);
            }
            else
            {
                const V t = V(-0.4, 0.5, 2.0).normalized();
                V radial = randomUnit(gen);
                radial = (radial - radial.dot(t)*t).normalized();
                x = o + 3*U(gen)*t + dist*radial;
            }

            const SurfacePoint p = c.project(x);
            ASSERT_TRUE(p.valid) << c.name;
            expectConsistent(c, x, p, 32*eps*(1 + x.norm() + R));

            // h ~ 1e-6 of the point's size: truncation O(h^2/dist^2) <=
            // 1e-9 at the nearest (0.05 R), round-off O(eps |x|/h) ~ 1e-10
            const double h = 1e-6*(1 + x.norm())/4;
            V g;
            for (int d = 0; d < 3; ++d)
            {
                V xp = x, xm = x;
                xp(d) += h;
                xm(d) -= h;
                g(d) = (c.project(xp).gap - c.project(xm).gap)/(2*h);
            }
            maxErr = std::max(maxErr, (g - p.normal).norm());
            ++n;
        }
        EXPECT_EQ(n, 400);
        EXPECT_LT(maxErr, 1e-7) << c.name;
    }
}


TEST(analyticSurface, pointsWithin1em12OfTheSurface)
{
    const FpeTraps traps(FE_OVERFLOW | FE_DIVBYZERO | FE_INVALID);
    std::mt19937 gen(7);
    for (const V& o : {V(0.3, -0.7, 1.1), V(1e6, -1e6, 1e6)})
    {
        for (const double R : {1e-9, 1.0, 1e3})
        {
            for (const Case& c : cases(o, R))
            {
                for (int i = 0; i < 20; ++i)
                {
                    // A point on the surface, then 1e-12 off it either way
                    const SurfacePoint s = c.project(o + 2*R*randomUnit(gen));
                    for (const double g : {-1e-12, 0.0, 1e-12})
                    {
                        const V x = s.point + g*s.normal;
                        const SurfacePoint p = c.project(x);
                        const double tol = 32*eps*(x.norm() + R);
                        EXPECT_TRUE(p.valid) << c.name;
                        expectConsistent(c, x, p, tol);
                        EXPECT_NEAR(p.gap, g, tol) << c.name << " R = " << R;
                        // Where the rounding resolves 1e-12, the sign is right
                        if (tol < 1e-13 && g != 0)
                        {
                            EXPECT_EQ(p.gap > 0, g > 0) << c.name;
                        }
                    }
                }
            }
        }
    }
}


TEST(analyticSurface, hugeCoordinatesAndTinyRadius)
{
    const FpeTraps traps(FE_OVERFLOW | FE_DIVBYZERO | FE_INVALID);
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (const V& o : {V(0, 0, 0), V(1e6, -1e6, 1e6)})
    {
        for (const double R : {1e-9, 1e-3, 1e6})
        {
            for (const Case& c : cases(o, R))
            {
                for (int i = 0; i < 50; ++i)
                {
                    // Distances 1e-9 .. 1e6 from the centre/axis/plane
                    const double dist = std::pow(10.0, -9 + 15*0.5*(U(gen) + 1));
                    const V x = o + dist*randomUnit(gen);
                    const SurfacePoint p = c.project(x);
                    expectConsistent(c, x, p, 32*eps*(x.norm() + R));
                }
            }
        }
    }
}


TEST(analyticSurface, onTheCentreOrAxisIsInvalidButFinite)
{
    const FpeTraps traps(FE_OVERFLOW | FE_DIVBYZERO | FE_INVALID);
    for (const V& o : {V(0, 0, 0), V(0.3, -0.7, 1.1), V(1e6, -1e6, 1e6)})
    {
        for (const double R : {1e-9, 1.0, 1e6})
        {
            for (const bool inside : {false, true})
            {
                const double sign = inside ? -1 : 1;

                // Exactly on the centre, and within 1e-300 of it
                // (subnormal offsets included): the fixed +-y normal
                for (const V& off : {V(0, 0, 0), V(1e-301, -1e-305, 0), V(0, 0, 4e-320)})
                {
                    const V x = o + off;
                    const SurfacePoint p = closestOnSphere(x, o, R, inside);
                    EXPECT_FALSE(p.valid);
                    ASSERT_TRUE(p.point.allFinite());
                    ASSERT_TRUE(p.normal.allFinite());
                    EXPECT_EQ(p.normal, sign*V(0, 1, 0));
                    EXPECT_NEAR((p.point - o).norm(), R, 4*eps*(o.norm() + R));
                    // R - |x - c| inside, |x - c| - R outside
                    EXPECT_NEAR(p.gap, -sign*R, 4*eps*R + 1e-299);
                    EXPECT_NEAR((x - p.point).dot(p.normal), p.gap, 4*eps*(o.norm() + R));
                }
                // Just beyond the threshold: a proper direction
                const SurfacePoint q = closestOnSphere(V(1e-299, 0, 0), V(0, 0, 0), R, inside);
                EXPECT_TRUE(q.valid);
                EXPECT_EQ(q.normal, sign*V(1, 0, 0));

                // On an axis along a coordinate direction, anywhere along
                // it: the radial offset is exactly zero
                for (const V& e : {V(0, 0, 1), V(0, -2, 0), V(7, 0, 0)})
                {
                    for (const double s : {0.0, 1e-12, -3.5, 1e6})
                    {
                        const V x = o + s*e.normalized();
                        const SurfacePoint p = closestOnCylinder(x, o, e, R, inside);
                        EXPECT_FALSE(p.valid) << e.transpose() << " " << s;
                        ASSERT_TRUE(p.normal.allFinite());
                        ASSERT_TRUE(p.point.allFinite());
                        EXPECT_NEAR(p.normal.norm(), 1.0, 4*eps);
                        EXPECT_EQ(p.normal.dot(e), 0.0);
                        EXPECT_EQ(p.gap, -sign*R);
                        EXPECT_NEAR((p.point - x).norm(), R, 8*eps*(x.norm() + R));
                    }
                }

                // A general axis: a point on it is only on it to rounding,
                // so it may be valid with a direction of rounding noise,
                // but the normal is still unit and across the axis, the
                // point on the surface and the gap -R to rounding
                for (const V& e : {V(1, 1, 1), V(-0.4, 0.5, 2.0), V(1e-200, 3e-200, -2e-200), V(1e200, 0, -1e200)})
                {
                    // Normalised after scaling: e.normalized() of 1e200
                    // would overflow in its square
                    const V tn = (e/e.cwiseAbs().maxCoeff()).normalized();
                    for (const double s : {0.0, 1e-12, -3.5, 1e6})
                    {
                        const V x = o + s*tn;
                        const SurfacePoint p = closestOnCylinder(x, o, e, R, inside);
                        ASSERT_TRUE(p.normal.allFinite());
                        ASSERT_TRUE(p.point.allFinite());
                        ASSERT_TRUE(std::isfinite(p.gap));
                        EXPECT_NEAR(p.normal.norm(), 1.0, 4*eps);
                        EXPECT_NEAR(p.normal.dot(tn), 0.0, 8*eps);
                        const double tol = 16*eps*(x.norm() + R);
                        EXPECT_NEAR(p.gap, -sign*R, tol);
                        const V d = p.point - o;
                        EXPECT_NEAR((d - d.dot(tn)*tn).norm(), R, tol);
                    }
                }
            }
        }
    }

    // The fallback is deterministic: the same input, the same normal
    const SurfacePoint a = closestOnCylinder(V(1, 1, 1), V(1, 1, 1), V(1, 1, 1), 2.0);
    const SurfacePoint b = closestOnCylinder(V(1, 1, 1), V(1, 1, 1), V(1, 1, 1), 2.0);
    EXPECT_FALSE(a.valid);
    EXPECT_EQ(a.normal, b.normal);
    EXPECT_EQ(a.point, b.point);
}


TEST(analyticSurface, invalidRadiusOrAxisThrows)
{
    const double NaN = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const V x(1, 2, 3), o(0, 0, 0), ez(0, 0, 1);
    for (const double R : {0.0, -1.0, -0.0, NaN, inf})
    {
        for (const bool inside : {false, true})
        {
            EXPECT_THROW(closestOnSphere(x, o, R, inside), std::invalid_argument) << R;
            EXPECT_THROW(closestOnCylinder(x, o, ez, R, inside), std::invalid_argument) << R;
        }
    }
    for (const V& bad : {V(0, 0, 0), V(NaN, 0, 1), V(0, inf, 0)})
    {
        EXPECT_THROW(closestOnCylinder(x, o, bad, 1.0), std::invalid_argument);
        EXPECT_THROW(closestOnPlane(x, o, bad), std::invalid_argument);
    }
    // Any non-zero length is a direction, without under- or overflow
    for (const double s : {1e-300, 1e-200, 1.0, 1e200, 1e300})
    {
        const SurfacePoint p = closestOnPlane(x, o, s*V(0, 3, 4));
        EXPECT_NEAR((p.normal - V(0, 0.6, 0.8)).norm(), 0.0, 4*eps) << s;
        EXPECT_NEAR(p.gap, 0.6*2 + 0.8*3, 8*eps) << s;
        const SurfacePoint q = closestOnCylinder(V(0, 5, 7), o, s*ez, 2.0);
        EXPECT_EQ(q.gap, 3.0) << s;
    }
}
