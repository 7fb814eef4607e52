/*---------------------------------------------------------------------------*\
  contact4foam: unit tests of the matrix-free GMRES kernel
\*---------------------------------------------------------------------------*/
// src/kernels/coupling/gmres. Checked against Eigen's dense LU on random
// non-symmetric systems (GMRES on an n x n system is exact after n
// products: Saad & Schultz 1986), against the true residual |b - A x| for
// the least squares' estimate, on the degenerate inputs (zero right-hand
// side, identity, a singular operator, a product that turns non-finite),
// and used the way the Newton-Krylov loop uses it: finite-difference
// products of a fixed-point map, where Newton's quadratic convergence is
// the check.

#include "gmres.H"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

using namespace c4f::coupling;

namespace
{

using Vec = std::vector<double>;

Eigen::MatrixXd randomMatrix(int n, unsigned seed, double diagonal)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    Eigen::MatrixXd A(n, n);
    for (int i = 0; i < n; ++i)
    {
        for (int j = 0; j < n; ++j)
        {
            A(i, j) = u(gen)/std::sqrt(double(n));
        }
        A(i, i) += diagonal;
    }
    return A;
}

Gmres::Operator dense(const Eigen::MatrixXd& A)
{
    return [A](const Vec& v, Vec& y)
    {
        const Eigen::Map<const Eigen::VectorXd> vm(v.data(), v.size());
        const Eigen::VectorXd r = A*vm;
        y.assign(r.data(), r.data() + r.size());
    };
}

Vec randomVector(int n, unsigned seed)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    Vec b(n);
    for (double& bi : b)
    {
        bi = u(gen);
    }
    return b;
}

double trueResidual(const Eigen::MatrixXd& A, const Vec& b, const Vec& x)
{
    const Eigen::Map<const Eigen::VectorXd> bm(b.data(), b.size());
    const Eigen::Map<const Eigen::VectorXd> xm(x.data(), x.size());
    return (bm - A*xm).norm();
}

} // End anonymous namespace


TEST(Gmres, ExactAfterNProductsAgainstDenseLU)
{
    const int n = 25;
    const Eigen::MatrixXd A = randomMatrix(n, 7, 0.3);
    const Vec b = randomVector(n, 8);

    GmresParameters p;
    p.maxIterations = n;
    p.relativeTolerance = 1e-13;
    const Gmres gmres(p);
    Vec x;
    const GmresResult r = gmres.solve(dense(A), b, x);

    const Eigen::VectorXd ref =
        A.partialPivLu().solve(Eigen::Map<const Eigen::VectorXd>(b.data(), n));
    ASSERT_EQ(int(x.size()), n);
    for (int i = 0; i < n; ++i)
    {
        EXPECT_NEAR(x[i], ref(i), 1e-9*ref.norm());
    }
    EXPECT_LE(r.iterations, n);
}


TEST(Gmres, EstimatedResidualIsTheTrueOneAndMeetsTheTolerance)
{
    for (unsigned seed = 1; seed <= 5; ++seed)
    {
        const int n = 60;
        const Eigen::MatrixXd A = randomMatrix(n, seed, 1.5);
        const Vec b = randomVector(n, 100 + seed);

        for (const double tol : {1e-1, 1e-3, 1e-8})
        {
            GmresParameters p;
            p.maxIterations = n;
            p.relativeTolerance = tol;
            Vec x;
            const GmresResult r = Gmres(p).solve(dense(A), b, x);
            ASSERT_TRUE(r.converged) << "seed " << seed << " tol " << tol;
            const double t = trueResidual(A, b, x);
            EXPECT_NEAR(t, r.residualNorm, 1e-10*r.initialNorm);
            EXPECT_LE(t, tol*r.initialNorm*(1 + 1e-8));
            // A well-conditioned system converges long before n
            EXPECT_LT(r.iterations, n);
        }
    }
}


TEST(Gmres, ResidualNeverGrowsWithMoreProducts)
{
    const int n = 40;
    const Eigen::MatrixXd A = randomMatrix(n, 3, 0.2);
    const Vec b = randomVector(n, 4);
    double previous = std::numeric_limits<double>::infinity();
    for (int k = 1; k <= n; ++k)
    {
        GmresParameters p;
        p.maxIterations = k;
        p.relativeTolerance = 1e-14;
        Vec x;
        Gmres(p).solve(dense(A), b, x);
        const double t = trueResidual(A, b, x);
        EXPECT_LE(t, previous*(1 + 1e-10)) << k << " products";
        previous = t;
    }
}


TEST(Gmres, DegenerateInputs)
{
    const int n = 10;
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);

    // Zero right-hand side: x = 0 without a product
    {
        Vec x;
        const GmresResult r = Gmres().solve(dense(I), Vec(n, 0.0), x);
        EXPECT_TRUE(r.converged);
        EXPECT_EQ(r.iterations, 0);
        for (const double xi : x)
        {
            EXPECT_EQ(xi, 0.0);
        }
    }

    // The identity: the basis breaks down after one product, x = b
    {
        const Vec b = randomVector(n, 11);
        GmresParameters p;
        p.relativeTolerance = 1e-15;
        Vec x;
        const GmresResult r = Gmres(p).solve(dense(I), b, x);
        EXPECT_TRUE(r.converged);
        EXPECT_EQ(r.iterations, 1);
        for (int i = 0; i < n; ++i)
        {
            EXPECT_NEAR(x[i], b[i], 1e-15);
        }
    }

    // A singular operator with b outside its range: no convergence, a
    // finite least-squares iterate, and the residual not above |b|
    {
        Eigen::MatrixXd S = Eigen::MatrixXd::Identity(n, n);
        S(0, 0) = 0;
        Vec b(n, 0.0);
        b[0] = 1;
        b[1] = 1;
        Vec x;
        const GmresResult r = Gmres().solve(dense(S), b, x);
        EXPECT_FALSE(r.converged);
        for (const double xi : x)
        {
            EXPECT_TRUE(std::isfinite(xi));
        }
        EXPECT_LE(trueResidual(S, b, x), r.initialNorm*(1 + 1e-12));
    }

    // A product that turns non-finite: stop, unconverged, finite x
    {
        const Eigen::MatrixXd A = randomMatrix(n, 5, 0.1);
        int calls = 0;
        const Gmres::Operator op = [&](const Vec& v, Vec& y)
        {
            dense(A)(v, y);
            if (++calls == 3)
            {
                y[0] = std::numeric_limits<double>::quiet_NaN();
            }
        };
        GmresParameters p;
        p.relativeTolerance = 1e-14;
        Vec x;
        const Vec b = randomVector(n, 6);
        const GmresResult r = Gmres(p).solve(op, b, x);
        EXPECT_FALSE(r.converged);
        EXPECT_EQ(r.iterations, 3);
        for (const double xi : x)
        {
            EXPECT_TRUE(std::isfinite(xi));
        }
        EXPECT_LT(trueResidual(A, b, x), r.initialNorm);
    }

    // An operator answering the wrong size is refused
    {
        const Gmres::Operator bad = [](const Vec&, Vec& y)
        {
            y.assign(3, 1.0);
        };
        Vec x;
        EXPECT_THROW(Gmres().solve(bad, Vec(n, 1.0), x), std::invalid_argument);
    }
}


TEST(Gmres, ParametersOutOfRangeAreRefused)
{
    GmresParameters p;
    p.maxIterations = 0;
    EXPECT_THROW(Gmres::check(p), std::invalid_argument);
    p = GmresParameters();
    for (const double tol : {0.0, 1.0, -1e-3, std::nan("")})
    {
        p.relativeTolerance = tol;
        EXPECT_THROW(Gmres{p}, std::invalid_argument) << tol;
    }

    // A forcing term given to one solve is checked the same way
    const Gmres gmres;
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(3, 3);
    Vec x;
    for (const double tol : {0.0, 1.5, std::nan("")})
    {
        EXPECT_THROW(gmres.solve(dense(I), Vec(3, 1.0), x, tol), std::invalid_argument)
            << tol;
    }
    EXPECT_TRUE(gmres.solve(dense(I), Vec(3, 1.0), x, 0.5).converged);
}


// The Newton-Krylov use: x = G(x) with G(x) = x - P F(x), P a fixed
// approximate inverse (the segregated corrector's part), F smooth and
// nonlinear; products by finite differences of G. Newton with tight inner
// solves converges quadratically: the residual's digits double each step.
TEST(Gmres, JacobianFreeNewtonOnAFixedPointMapConvergesQuadratically)
{
    const int n = 30;
    const Eigen::MatrixXd K = randomMatrix(n, 21, 2.0);
    const Vec f = randomVector(n, 22);
    // P: the inverse of K's diagonal, a Jacobi sweep
    const auto G = [&](const Vec& x, Vec& g)
    {
        g.resize(n);
        const Eigen::Map<const Eigen::VectorXd> xm(x.data(), n);
        const Eigen::VectorXd Kx = K*xm;
        for (int i = 0; i < n; ++i)
        {
            const double F = Kx(i) + 0.5*std::pow(x[i], 3) - f[i];
            g[i] = x[i] - F/K(i, i);
        }
    };

    GmresParameters p;
    p.maxIterations = n;
    p.relativeTolerance = 1e-10;
    const Gmres gmres(p);

    Vec x(n, 0.0), g, gp, d, xp(n);
    std::vector<double> norms;
    for (int it = 0; it < 8; ++it)
    {
        G(x, g);
        Vec F(n);
        double nF = 0;
        for (int i = 0; i < n; ++i)
        {
            F[i] = g[i] - x[i];
            nF += F[i]*F[i];
        }
        norms.push_back(std::sqrt(nF));
        if (norms.back() < 1e-13)
        {
            break;
        }
        const Gmres::Operator J = [&](const Vec& v, Vec& y)
        {
            const double eps = 1e-7;
            for (int i = 0; i < n; ++i)
            {
                xp[i] = x[i] + eps*v[i];
            }
            G(xp, gp);
            y.resize(n);
            for (int i = 0; i < n; ++i)
            {
                y[i] = v[i] - (gp[i] - g[i])/eps;
            }
        };
        gmres.solve(J, F, d);
        for (int i = 0; i < n; ++i)
        {
            x[i] += d[i];
        }
    }
    ASSERT_GE(norms.size(), 3u);
    EXPECT_LT(norms.back(), 1e-12);
    EXPECT_LE(norms.size(), 7u);
    // Quadratic: once below 1e-2, each step at least squares the residual
    // (up to a constant), which a linearly convergent scheme cannot do
    for (std::size_t k = 1; k + 1 < norms.size(); ++k)
    {
        if (norms[k] < 1e-2 && norms[k + 1] > 1e-12)
        {
            EXPECT_LT(norms[k + 1], 10*norms[k]*norms[k]) << "step " << k;
        }
    }
}
