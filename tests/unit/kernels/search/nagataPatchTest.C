// Unit tests of the curved face patch, src/kernels/search/nagataPatch
// (Nagata 2005). Checked: the edge coefficient's two tangency conditions
// and its degenerate cases; a circular arc and a sphere reproduced to
// fourth order in the face size where the flat faces are second order;
// corners, corner normals and flat faces reproduced exactly; the curve two
// faces share is the same from both (a continuous surface); the
// derivatives against finite differences; the projection against a
// brute-force search of the parameter domain, inside and outside it.

#include "nagataPatch.H"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace c4f::search;
using V = Eigen::Vector3d;
using P = Eigen::Vector2d;

namespace
{

const double pi = 3.14159265358979323846;

V sphere(const double R, const double th, const double ph)
{
    return R*V(std::sin(th)*std::cos(ph), std::sin(th)*std::sin(ph), std::cos(th));
}

// A quad on the sphere of radius R about the pole, of angular size h
NagataPatch sphereQuad(const double R, const double h, std::vector<V>& x)
{
    x = {
        sphere(R, 0.3, 0.2), sphere(R, 0.3 + h, 0.2),
        sphere(R, 0.3 + h, 0.2 + h), sphere(R, 0.3, 0.2 + h)};
    std::vector<V> n;
    for (const V& p : x)
    {
        n.push_back(p.normalized());
    }
    return NagataPatch(x, n);
}

// The largest |(|x| - R)| over a grid of the patch's parameters
double radialError(const NagataPatch& s, const double R)
{
    double err = 0;
    for (int i = 0; i <= 10; ++i)
    {
        for (int j = 0; j <= 10; ++j)
        {
            P p(i/10.0, j/10.0);
            if (s.size() == 3 && p(1) > p(0))
            {
                continue;
            }
            err = std::max(err, std::abs(s.point(p).norm() - R));
        }
    }
    return err;
}

}


TEST(NagataEdge, TangentToBothEndPlanes)
{
    // Two points of a sphere (random centre, radius and points within a
    // quarter of its circumference) with the sphere's normals: the two
    // conditions hold and the coefficient is not shortened
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(-1, 1), r(0.1, 10);
    for (int k = 0; k < 200; ++k)
    {
        const V centre(u(gen), u(gen), u(gen));
        const double R = r(gen);
        const V a(V(u(gen), u(gen), u(gen)).normalized());
        const V b((a + 0.7*V(u(gen), u(gen), u(gen))).normalized());
        const V x0(centre + R*a), x1(centre + R*b);
        const V d(x1 - x0);
        const V c(nagataEdgeCoefficient(x0, x1, a, b));
        EXPECT_NEAR(a.dot(d - c), 0, 1e-10*d.norm());
        EXPECT_NEAR(b.dot(d + c), 0, 1e-10*d.norm());
        // An arc's |d| tan(phi/2)
        const double phi = std::acos(std::min(1.0, a.dot(b)));
        EXPECT_NEAR(c.norm(), d.norm()*std::tan(phi/2), 1e-9*d.norm());
    }
}


TEST(NagataEdge, DegenerateCases)
{
    const V x0(0, 0, 0), x1(1, 0, 0);
    // Parallel normals orthogonal to the edge: straight
    EXPECT_EQ(nagataEdgeCoefficient(x0, x1, V(0, 0, 1), V(0, 0, 1)), V::Zero());
    // Opposite normals (a fold): straight
    EXPECT_EQ(nagataEdgeCoefficient(x0, x1, V(0, 0, 1), V(0, 0, -1)), V::Zero());
    // A repeated point
    EXPECT_EQ
    (
        nagataEdgeCoefficient(x0, x0, V(0, 0, 1), V(0, 1, 0)), V::Zero()
    );
    // A normal nearly along the edge: shortened to |d|
    const V c
    (
        nagataEdgeCoefficient
        (
            x0, x1, V(1, 0, 0.05).normalized(), V(0, 0, 1)
        )
    );
    EXPECT_LE(c.norm(), 1 + 1e-12);
    EXPECT_TRUE(c.allFinite());

    // Nearly parallel normals, the chord leaning 0.3 degrees against them
    // (the deformed surface's case): the exact coefficient is of the
    // order of |d| itself; shortened to |d| phi
    const double phi = 0.005;
    const double lean = 0.3*3.14159265358979/180;
    const V y1(std::cos(lean), std::sin(lean), 0);
    const V m0(0, 1, 0), m1(-std::sin(phi), std::cos(phi), 0);
    const V cm(nagataEdgeCoefficient(x0, y1, m0, m1));
    EXPECT_LE(cm.norm(), phi*(1 + 1e-9));
    EXPECT_GT(cm.norm(), 0.5*phi);
    // Zero normals (a degenerate surface point) give finite values
    EXPECT_TRUE(nagataEdgeCoefficient(x0, x1, V::Zero(), V(0, 0, 1)).allFinite());
}


TEST(NagataEdge, CircularArcToFourthOrder)
{
    // Points at +-theta on a circle of radius R, exact normals
    const double R = 2;
    for (const double th : {0.2, 0.1, 0.05})
    {
        const V x0(-R*std::sin(th), R*std::cos(th), 0);
        const V x1(R*std::sin(th), R*std::cos(th), 0);
        const V c
        (
            nagataEdgeCoefficient(x0, x1, x0.normalized(), x1.normalized())
        );
        const V mid(0.5*(x0 + x1) - 0.25*c);
        const double t2 = std::pow(std::tan(th), 2);
        EXPECT_NEAR(mid.norm(), R*std::cos(th)*(1 + t2/2), 1e-12*R);
        // Fourth order: R (1 + theta^4/8) to leading order, where the
        // chord's midpoint is at R (1 - theta^2/2)
        EXPECT_NEAR((mid.norm() - R)/(R*std::pow(th, 4)), 0.125, 0.005);
    }
}


TEST(NagataPatch, SphereToFourthOrder)
{
    const double R = 1;
    double last = 0;
    for (const double h : {0.2, 0.1, 0.05})
    {
        std::vector<V> x;
        const NagataPatch s(sphereQuad(R, h, x));
        ASSERT_TRUE(s.valid());
        const double err = radialError(s, R);
        // The flat (bilinear) face's centre sits at about R h^2/4 inside
        const double flat = R - (0.25*(x[0] + x[1] + x[2] + x[3])).norm();
        EXPECT_LT(err, 0.05*flat);
        if (last > 0)
        {
            EXPECT_GT(last/err, 12.0);   // 16 for fourth order
        }
        last = err;

        // The triangle of the quad's first three corners
        const NagataPatch t
        (
            std::vector<V>{x[0], x[1], x[2]},
            std::vector<V>{x[0], x[1], x[2]}
        );
        EXPECT_LT(radialError(t, R), 0.1*flat);
    }
}


TEST(NagataPatch, CornersAndCornerNormals)
{
    std::vector<V> x;
    const NagataPatch s(sphereQuad(1, 0.1, x));
    for (int k = 0; k < 4; ++k)
    {
        EXPECT_LT((s.point(s.cornerParam(k)) - x[k]).norm(), 1e-14);
        // Right-handed with the point order: outward here
        EXPECT_LT((s.normal(s.cornerParam(k)) - x[k].normalized()).norm(), 1e-9);
    }
    const NagataPatch t
    (
        std::vector<V>{x[0], x[1], x[2]}, std::vector<V>{x[0], x[1], x[2]}
    );
    for (int k = 0; k < 3; ++k)
    {
        EXPECT_LT((t.point(t.cornerParam(k)) - x[k]).norm(), 1e-14);
        EXPECT_LT((t.normal(t.cornerParam(k)) - x[k].normalized()).norm(), 1e-9);
    }
}


TEST(NagataPatch, FlatFacesStayFlat)
{
    // A planar quad and triangle, turned, with their own normal at every
    // corner: the bilinear face and the flat triangle
    const Eigen::Matrix3d R
    (
        Eigen::AngleAxisd(0.7, V(1, 2, 3).normalized()).toRotationMatrix()
    );
    const std::vector<V> x =
        {R*V(0, 0, 0), R*V(2, 0, 0), R*V(2.5, 1, 0), R*V(-0.3, 1.2, 0)};
    const V n(R*V(0, 0, 1));
    const NagataPatch s(x, std::vector<V>(4, n));
    for (const P& p : {P(0.3, 0.7), P(0.5, 0.5), P(0.9, 0.1)})
    {
        const V bilinear
        (
            (1 - p(0))*(1 - p(1))*x[0] + p(0)*(1 - p(1))*x[1]
          + p(0)*p(1)*x[2] + (1 - p(0))*p(1)*x[3]
        );
        EXPECT_LT((s.point(p) - bilinear).norm(), 1e-14);
        EXPECT_LT((s.normal(p) - n).norm(), 1e-12);
    }
    const NagataPatch t
    (
        std::vector<V>{x[0], x[1], x[2]}, std::vector<V>(3, n)
    );
    const P p(0.6, 0.2);
    EXPECT_LT
    (
        (t.point(p) - (x[0] + (x[1] - x[0])*p(0) + (x[2] - x[1])*p(1))).norm(),
        1e-14
    );
}


TEST(NagataPatch, SharedEdgeIsContinuous)
{
    // Two quads of a sphere sharing the edge x1-x2 (the second's x0-x3),
    // and two triangles sharing a diagonal: the same curve from both
    const double R = 1.5, h = 0.15;
    const V a(sphere(R, 0.3, 0.2)), b(sphere(R, 0.3 + h, 0.2)),
        c(sphere(R, 0.3 + h, 0.2 + h)), d(sphere(R, 0.3, 0.2 + h)),
        e(sphere(R, 0.3 + 2*h, 0.2)), f(sphere(R, 0.3 + 2*h, 0.2 + h));
    const auto normals = [](const std::vector<V>& x)
    {
        std::vector<V> n;
        for (const V& p : x)
        {
            n.push_back(p.normalized());
        }
        return n;
    };
    const std::vector<V> q1 = {a, b, c, d}, q2 = {b, e, f, c};
    const NagataPatch s1(q1, normals(q1)), s2(q2, normals(q2));
    for (double t = 0; t <= 1; t += 0.125)
    {
        // s1's edge eta = 1 (b to c), s2's edge eta = 0 (b to c)
        EXPECT_LT((s1.point(P(1, t)) - s2.point(P(0, t))).norm(), 1e-14);
    }

    const std::vector<V> t1 = {a, b, c}, t2 = {a, c, d};
    const NagataPatch s3(t1, normals(t1)), s4(t2, normals(t2));
    for (double t = 0; t <= 1; t += 0.125)
    {
        // Both triangles' edge x00-x11... t1's a-c is zeta = eta, t2's
        // a-c is its edge zeta = 0
        EXPECT_LT((s3.point(P(t, t)) - s4.point(P(t, 0))).norm(), 1e-14);
    }
}


TEST(NagataPatch, DerivativesAgainstFiniteDifferences)
{
    std::vector<V> x;
    const NagataPatch quad(sphereQuad(1, 0.3, x));
    const NagataPatch tri
    (
        std::vector<V>{x[0], x[1], x[2]},
        std::vector<V>{x[0].normalized(), V(0.1, 0.2, 1).normalized(), x[2].normalized()}
    );
    const double eps = 1e-6;
    for (const NagataPatch* s : {&quad, &tri})
    {
        for (const P& p : {P(0.3, 0.1), P(0.8, 0.5), P(0.5, 0.45)})
        {
            const Eigen::Matrix<double, 3, 2> J(s->tangents(p));
            const Eigen::Matrix<double, 3, 3> S(s->secondDerivatives(p));
            for (int i = 0; i < 2; ++i)
            {
                const P dp(i == 0 ? P(eps, 0) : P(0, eps));
                const V fd((s->point(p + dp) - s->point(p - dp))/(2*eps));
                EXPECT_LT((fd - J.col(i)).norm(), 1e-8);
                const Eigen::Matrix<double, 3, 2> Jd
                (
                    (s->tangents(p + dp) - s->tangents(p - dp))/(2*eps)
                );
                // d/d eta of (x_eta, x_zeta) = (x_ee, x_ez); d/d zeta
                // = (x_ez, x_zz)
                EXPECT_LT((Jd.col(0) - S.col(i)).norm(), 1e-7);
                EXPECT_LT((Jd.col(1) - S.col(i + 1)).norm(), 1e-7);
            }
        }
    }
}


TEST(NagataPatch, ClosestPointAgainstBruteForce)
{
    std::vector<V> x;
    const double R = 1;
    const NagataPatch quad(sphereQuad(R, 0.3, x));
    const NagataPatch tri
    (
        std::vector<V>{x[0], x[1], x[2]},
        std::vector<V>{x[0].normalized(), x[1].normalized(), x[2].normalized()}
    );
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-0.2, 1.2), r(0.8, 1.2);
    int nInside = 0, nOutside = 0;
    for (const NagataPatch* s : {&quad, &tri})
    {
        for (int k = 0; k < 100; ++k)
        {
            // A point above or below a random spot of the patch (or past
            // its edges), at up to a fifth of R off the surface
            P p(u(gen), u(gen));
            const V q(s->point(p)*r(gen));
            const NagataProjection proj(s->closest(q));

            // Brute force over a fine grid of the domain
            double best = 1e30;
            const int N = 400;
            for (int i = 0; i <= N; ++i)
            {
                for (int j = 0; j <= N; ++j)
                {
                    const P g(double(i)/N, double(j)/N);
                    if (s->size() == 3 && g(1) > g(0))
                    {
                        continue;
                    }
                    best = std::min(best, (s->point(g) - q).norm());
                }
            }
            EXPECT_LE(proj.distance, best + 1e-12);
            // the grid's spacing 1/400 over tangents of about 0.3
            EXPECT_GT(proj.distance, best - 5e-4);
            EXPECT_NEAR(proj.distance, (proj.point - q).norm(), 1e-14);
            if (proj.inside)
            {
                // Orthogonal: q - x along the patch normal
                const V dx(q - proj.point);
                EXPECT_LT
                (
                    (dx - dx.dot(proj.normal)*proj.normal).norm(),
                    1e-8*std::max(1.0, dx.norm())
                );
                ++nInside;
            }
            else
            {
                ++nOutside;
            }
        }
    }
    // Both kinds were exercised
    EXPECT_GT(nInside, 20);
    EXPECT_GT(nOutside, 20);
}


TEST(NagataPatch, InvalidFacesAndRepeatedPoints)
{
    const std::vector<V> pent =
        {V(0, 0, 0), V(1, 0, 0), V(1.5, 1, 0), V(0.5, 1.5, 0), V(-0.5, 1, 0)};
    const NagataPatch s(pent, std::vector<V>(5, V(0, 0, 1)));
    EXPECT_FALSE(s.valid());
    EXPECT_FALSE(s.closest(V(0, 0, 1)).inside);

    // A quad with a repeated point (a collapsed edge): finite everywhere
    const std::vector<V> x = {V(0, 0, 0), V(1, 0, 0), V(1, 0, 0), V(0, 1, 0.1)};
    const NagataPatch d(x, std::vector<V>(4, V(0, 0, 1)));
    const NagataProjection proj(d.closest(V(0.4, 0.3, 1)));
    EXPECT_TRUE(proj.point.allFinite());
    EXPECT_TRUE(std::isfinite(proj.distance));
    EXPECT_NEAR(proj.point.z(), 0.03, 0.05);
}


TEST(NagataPatch, SmallFaceFarFromTheOrigin)
{
    // A face 1e-3 across at 1e3 from the origin (the coordinates 1e6
    // times the face): the closest point of a point above its interior
    // is inside and orthogonal, not an edge's
    const V o(1e3, -2e3, 5e2);
    std::vector<V> x;
    const NagataPatch unit(sphereQuad(1, 0.2, x));
    std::vector<V> y, n;
    for (const V& p : x)
    {
        y.push_back(o + 5e-3*p);
        n.push_back(p.normalized());
    }
    const NagataPatch s(y, n);
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(0.1, 0.9), r(0.9, 1.1);
    for (int k = 0; k < 50; ++k)
    {
        const P p(u(gen), u(gen));
        const V q(o + (s.point(p) - o)*r(gen));
        const NagataProjection proj(s.closest(q));
        EXPECT_TRUE(proj.inside);
        const V dx(q - proj.point);
        EXPECT_LT((dx - dx.dot(proj.normal)*proj.normal).norm(), 1e-9*5e-3);
    }
}


TEST(NagataPatch, BulgeBoundsTheDistanceFromTheCornersInterpolation)
{
    // Random faces with random unit corner normals (up to the edge cap,
    // then at it): over a parameter grid the patch stays within bulge()
    // of the bilinear (quad) or linear (triangle) interpolation of its
    // corners, and the bound is not loose by more than its four terms
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 200; ++trial)
    {
        const int n = trial % 2 ? 3 : 4;
        std::vector<V> x
        {
            V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0)
        };
        x.resize(n);
        std::vector<V> nrm;
        for (V& p : x)
        {
            p += 0.2*V(u(gen), u(gen), u(gen));
            const double lean = trial < 100 ? 0.3 : 1.5;
            nrm.push_back((V(0, 0, 1) + lean*V(u(gen), u(gen), 0)).normalized());
        }
        const NagataPatch s(x, nrm);
        ASSERT_TRUE(s.valid());
        double most = 0;
        for (int i = 0; i <= 20; ++i)
        {
            for (int j = 0; j <= 20; ++j)
            {
                const double e = i/20.0, z = j/20.0;
                V lin;
                if (n == 4)
                {
                    lin = (1 - e)*(1 - z)*x[0] + e*(1 - z)*x[1] + e*z*x[2]
                        + (1 - e)*z*x[3];
                }
                else
                {
                    if (z > e)
                    {
                        continue;
                    }
                    lin = x[0] + (x[1] - x[0])*e + (x[2] - x[1])*z;
                }
                most = std::max(most, (s.point(P(e, z)) - lin).norm());
            }
        }
        EXPECT_LE(most, s.bulge()*(1 + 1e-12) + 1e-15) << "trial " << trial;
        EXPECT_GE(most, s.bulge()/(4*n)) << "trial " << trial;
    }

    // Flat faces and straight extrusion edges: no bulge
    const std::vector<V> flat{V(0, 0, 0), V(1, 0, 0), V(1, 1, 0), V(0, 1, 0)};
    const std::vector<V> up(4, V(0, 0, 1));
    EXPECT_EQ(NagataPatch(flat, up).bulge(), 0.0);
}
