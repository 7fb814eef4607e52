/*---------------------------------------------------------------------------*\
  contact4foam: unit tests of Anderson acceleration (IQN-ILS)
\*---------------------------------------------------------------------------*/
// src/kernels/coupling/andersonAcceleration. References: Walker & Ni 2011
// (SIAM J. Numer. Anal. 49:1715) for the method and its equivalence with
// GMRES on linear maps (hence the n + 1 bound below); Degroote, Bathe &
// Vierendeels 2009 (Comput. Struct. 87:793) for IQN-ILS. The step is
// checked against an independent dense least-squares solve (QR), and the
// parallel form against the serial one with a simulated all-reduce:
// threads that meet in the reduction, with a timeout that turns a hang
// into a failure.
//
// Shared setup lives in helpers rather than a ::testing::Test fixture: a
// fixture must carry the suite's name, AndersonAcceleration, which would
// hide the class under test inside every test body, and renaming the
// suite would change the test names that filters and logs rely on.

#include "andersonAcceleration.H"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <functional>
#include <iostream>
#include <limits>
#include <mutex>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace c4f::coupling;
using Vec = Eigen::VectorXd;
using Mat = Eigen::MatrixXd;

namespace
{

// Uniform in [-1, 1] from the raw engine output, so that the numbers do
// not depend on the standard library's distributions
double uniform(std::mt19937& gen)
{
    return 2.0*(static_cast<double>(gen())/4294967296.0) - 1.0;
}

Vec randomVector(const int n, std::mt19937& gen)
{
    Vec v(n);
    for (int i = 0; i < n; ++i)
    {
        v(i) = uniform(gen);
    }
    return v;
}

// A random (non-normal) matrix scaled to spectral radius rho
Mat randomContraction(const int n, const double rho, std::mt19937& gen)
{
    Mat A(n, n);
    for (int i = 0; i < n; ++i)
    {
        for (int j = 0; j < n; ++j)
        {
            A(i, j) = uniform(gen);
        }
    }
    const double r = A.eigenvalues().cwiseAbs().maxCoeff();
    return (rho/r)*A;
}

// Q diag(lambda) Q^T with a random orthogonal Q
Mat symmetricWithSpectrum(const Vec& lambda, std::mt19937& gen)
{
    const int n = lambda.size();
    Mat R(n, n);
    for (int j = 0; j < n; ++j)
    {
        R.col(j) = randomVector(n, gen);
    }
    const Mat Q = R.householderQr().householderQ();
    return Q*lambda.asDiagonal()*Q.transpose();
}

// One mode with factor -1.2, the others in [-spread, spread]; symmetric,
// so that the spectrum is exactly the one asked for
Mat withDivergingMode(const int n, const double spread, std::mt19937& gen)
{
    Vec lambda(n);
    lambda(0) = -1.2;
    for (int i = 1; i < n; ++i)
    {
        lambda(i) = spread*uniform(gen);
    }
    return symmetricWithSpectrum(lambda, gen);
}

using MapFn = std::function<Vec(const Vec&)>;

// x = cos x has the single real root 0.739085133215160641...
const double dottie = 0.7390851332151607;

Vec cosine(const Vec& x)
{
    return x.array().cos().matrix();
}

// G(x) = xStar + A (x - xStar): the fixed point is xStar to round-off
MapFn linearMap(const Mat& A, const Vec& xStar)
{
    return [A, xStar](const Vec& x) -> Vec { return xStar + A*(x - xStar); };
}

// A linear map with its fixed point and a start, drawn in this order from
// one seed so that each test's numbers stay reproducible; gen stays with
// it for tests that draw more
struct LinearProblem
{
    LinearProblem
    (
        const unsigned seed,
        const std::function<Mat(std::mt19937&)>& makeA
    )
    :
        gen(seed),
        A(makeA(gen)),
        xStar(randomVector(A.rows(), gen)),
        x0(randomVector(A.rows(), gen)),
        G(linearMap(A, xStar))
    {}

    // A random contraction, the common case
    LinearProblem(const int n, const unsigned seed, const double rho)
    :
        LinearProblem
        (
            seed,
            [n, rho](std::mt19937& g) { return randomContraction(n, rho, g); }
        )
    {}

    std::mt19937 gen;
    Mat A;
    Vec xStar;
    Vec x0;
    MapFn G;
};

AndersonAcceleration::Parameters params(const int depth, const double beta)
{
    AndersonAcceleration::Parameters p;
    p.depth = depth;
    p.beta = beta;
    return p;
}

// One update into a separate output, so that aliasing is tested only where
// a test asks for it
Vec step(AndersonAcceleration& aa, const Vec& x, const Vec& g)
{
    Vec xNext(x.size());
    aa.update(x.data(), g.data(), xNext.data(), x.size());
    return xNext;
}

// A fixed number of updates without a convergence check, to build up a
// history before the event a test is about
Vec iterate(AndersonAcceleration& aa, const MapFn& G, Vec x, const int nSteps)
{
    for (int k = 0; k < nSteps; ++k)
    {
        x = step(aa, x, G(x));
    }
    return x;
}

struct Outcome
{
    int iterations;     // updates until the error was below tol; -1: never
    double error;       // relative error at the end
    bool finite;
};

double relError(const Vec& x, const Vec& xStar)
{
    return (x - xStar).norm()/xStar.norm();
}

// Accelerated iteration from x0: the number of updates after which
// |x - xStar| <= tol |xStar|
Outcome accelerate
(
    AndersonAcceleration& aa,
    const MapFn& G,
    Vec x,
    const Vec& xStar,
    const double tol,
    const int maxIt
)
{
    for (int k = 0; k <= maxIt; ++k)
    {
        if (!x.allFinite())
        {
            return {-1, std::numeric_limits<double>::infinity(), false};
        }
        const double e = relError(x, xStar);
        if (e <= tol)
        {
            return {k, e, true};
        }
        x = step(aa, x, G(x));
    }
    return {-1, relError(x, xStar), x.allFinite()};
}

// The same from a fresh accelerator, for tests that look only at the count
Outcome accelerate
(
    const AndersonAcceleration::Parameters& p,
    const MapFn& G,
    const Vec& x0,
    const Vec& xStar,
    const double tol,
    const int maxIt
)
{
    AndersonAcceleration aa(p);
    return accelerate(aa, G, x0, xStar, tol, maxIt);
}

// Plain iteration x <- G(x), same counting
Outcome plain(const MapFn& G, Vec x, const Vec& xStar, const double tol, const int maxIt)
{
    for (int k = 0; k <= maxIt; ++k)
    {
        const double e = relError(x, xStar);
        if (e <= tol)
        {
            return {k, e, true};
        }
        x = G(x);
    }
    return {-1, relError(x, xStar), x.allFinite()};
}


// An all-reduce over nRanks simulated processors (threads): every rank
// calls reduce(rank, ...); the last to arrive sums the contributions in
// rank order and everyone leaves with the same sums. A rank that never
// arrives makes the others throw after the timeout instead of hanging.
class SimulatedAllReduce
{
public:

    explicit SimulatedAllReduce(const int nRanks)
    :
        contrib_(nRanks)
    {}

    void reduce(const int rank, double* data, const int count)
    {
        std::unique_lock<std::mutex> lock(mutex_);
        contrib_[rank].assign(data, data + count);
        const long generation = generation_;
        if (++arrived_ == static_cast<int>(contrib_.size()))
        {
            total_ = contrib_[0];
            for (std::size_t r = 1; r < contrib_.size(); ++r)
            {
                if (contrib_[r].size() != total_.size())
                {
                    countMismatch_ = true;
                }
                for (std::size_t i = 0; i < total_.size() && i < contrib_[r].size(); ++i)
                {
                    total_[i] += contrib_[r][i];
                }
            }
            arrived_ = 0;
            ++generation_;
            ++calls_;
            cv_.notify_all();
        }
        else if
        (
            !cv_.wait_for
            (
                lock,
                std::chrono::seconds(5),
                [&] { return generation_ != generation; }
            )
        )
        {
            throw std::runtime_error("rank " + std::to_string(rank) + " waited for ever");
        }
        for (int i = 0; i < count && i < static_cast<int>(total_.size()); ++i)
        {
            data[i] = total_[i];
        }
    }

    bool countMismatch() const { return countMismatch_; }
    long calls() const { return calls_; }

private:

    std::mutex mutex_;
    std::condition_variable cv_;
    std::vector<std::vector<double>> contrib_;
    std::vector<double> total_;
    int arrived_ = 0;
    long generation_ = 0;
    long calls_ = 0;
    bool countMismatch_ = false;
};


struct ParallelOutcome
{
    double maxDiff;     // largest |x_serial - x_slices| / |x*|
    int maxColumns;     // of the serial run
    int dropped, skipped, restarts;     // of the serial run
};

// Run the same iteration serially and split into slices (one object per
// slice, meeting in the simulated reduction); compare the iterates, and
// check on the way that all slices hold the same gamma bit for bit
ParallelOutcome parallelDifference
(
    const std::vector<int>& sliceSizes,
    const AndersonAcceleration::Parameters& p,
    const std::function<Vec(const Vec&, int k)>& G,
    const Vec& x0,
    const Vec& xStar,
    const int nIter
)
{
    const int n = x0.size();
    const int nRanks = sliceSizes.size();

    AndersonAcceleration serial(p);

    SimulatedAllReduce comm(nRanks);
    std::vector<AndersonAcceleration> ranks;
    ranks.reserve(nRanks);
    std::vector<int> offset(nRanks + 1, 0);
    for (int r = 0; r < nRanks; ++r)
    {
        ranks.emplace_back
        (
            p,
            [&comm, r](double* d, int c) { comm.reduce(r, d, c); }
        );
        offset[r + 1] = offset[r] + sliceSizes[r];
    }
    EXPECT_EQ(offset[nRanks], n);

    Vec xs = x0, xp = x0;
    double maxDiff = 0;
    int maxColumns = 0;
    for (int k = 0; k < nIter; ++k)
    {
        xs = step(serial, xs, G(xs, k));

        const Vec gp = G(xp, k);
        Vec xpNext(n);
        std::vector<std::exception_ptr> errors(nRanks);
        std::vector<std::thread> threads;
        for (int r = 0; r < nRanks; ++r)
        {
            threads.emplace_back
            (
                [&, r]
                {
                    try
                    {
                        ranks[r].update
                        (
                            xp.data() + offset[r],
                            gp.data() + offset[r],
                            xpNext.data() + offset[r],
                            sliceSizes[r]
                        );
                    }
                    catch (...)
                    {
                        errors[r] = std::current_exception();
                    }
                }
            );
        }
        for (auto& t : threads)
        {
            t.join();
        }
        for (int r = 0; r < nRanks; ++r)
        {
            if (errors[r])
            {
                try
                {
                    std::rethrow_exception(errors[r]);
                }
                catch (const std::exception& e)
                {
                    ADD_FAILURE() << "rank " << r << ": " << e.what();
                    return {std::numeric_limits<double>::infinity(), 0, 0, 0, 0};
                }
            }
        }
        xp = xpNext;

        for (int r = 1; r < nRanks; ++r)
        {
            EXPECT_EQ(ranks[r].nColumns(), ranks[0].nColumns());
            EXPECT_TRUE(ranks[r].gamma() == ranks[0].gamma())
                << "gamma differs between ranks at iteration " << k;
        }
        EXPECT_EQ(ranks[0].nColumns(), serial.nColumns()) << "iteration " << k;
        maxColumns = std::max(maxColumns, serial.nColumns());

        maxDiff = std::max(maxDiff, (xs - xp).norm()/xStar.norm());
    }
    EXPECT_FALSE(comm.countMismatch());
    // Exactly one reduction per update, on every rank
    EXPECT_EQ(comm.calls(), nIter);
    return
    {
        maxDiff, maxColumns,
        serial.nDropped(), serial.nSkipped(), serial.nRestarts()
    };
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Linear maps * * * * * * * * * * * * * * * //

// With a depth of at least n, Anderson with beta = 1 is GMRES in
// disguise (Walker & Ni 2011, sec. 2): x_{k+1} = G(GMRES iterate k), and
// GMRES is exact after n steps
TEST(AndersonAcceleration, LinearContractionFullDepthConvergesInAboutNPlusOneSteps)
{
    const int n = 20;
    const LinearProblem lp(n, 20240611, 0.95);

    for (const int depth : {n, n + 10})
    {
        const Outcome run = accelerate(params(depth, 1.0), lp.G, lp.x0, lp.xStar, 1e-10, 200);
        ASSERT_TRUE(run.finite);
        ASSERT_GE(run.iterations, 0) << "did not converge, error " << run.error;
        std::cout << "[ depth " << depth << " ] " << run.iterations
                  << " iterations to 1e-10 (n + 1 = " << n + 1 << ")\n";
        EXPECT_LE(run.iterations, n + 2);
        EXPECT_LE(run.error, 1e-10);
    }
}

TEST(AndersonAcceleration, LinearContractionDepthFiveBeatsPlainIteration)
{
    const LinearProblem lp(20, 20240611, 0.95);

    const Outcome p = plain(lp.G, lp.x0, lp.xStar, 1e-10, 20000);
    ASSERT_GT(p.iterations, 0) << "plain iteration did not converge";

    for (const double beta : {1.0, 0.5})
    {
        AndersonAcceleration aa(params(5, beta));
        const Outcome a = accelerate(aa, lp.G, lp.x0, lp.xStar, 1e-10, 20000);
        ASSERT_GT(a.iterations, 0) << "beta " << beta << ": error " << a.error;
        const double ratio = double(p.iterations)/a.iterations;
        std::cout << "[ beta " << beta << " ] plain " << p.iterations
                  << ", Anderson(5) " << a.iterations
                  << " iterations, ratio " << ratio << '\n';
        EXPECT_GE(ratio, 5.0) << "beta " << beta;
        EXPECT_LE(aa.nColumns(), 5);
    }
}

// One mode with factor -1.2 (a Dirichlet-Neumann interface of a stiff
// Dirichlet side): the plain iteration oscillates with growing amplitude,
// Anderson converges because I - A is non-singular
TEST(AndersonAcceleration, DivergingOscillatingModeConverges)
{
    const LinearProblem lp
    (
        7,
        [](std::mt19937& gen) { return withDivergingMode(20, 0.9, gen); }
    );

    // The plain iteration really diverges here
    Vec x = lp.x0;
    for (int k = 0; k < 60; ++k)
    {
        x = lp.G(x);
    }
    EXPECT_GT(relError(x, lp.xStar), 1e3*relError(lp.x0, lp.xStar));

    for (const int depth : {2, 5})
    {
        const Outcome a = accelerate(params(depth, 1.0), lp.G, lp.x0, lp.xStar, 1e-10, 300);
        EXPECT_TRUE(a.finite);
        EXPECT_GT(a.iterations, 0) << "depth " << depth << ": error " << a.error;
        std::cout << "[ depth " << depth << " ] " << a.iterations << " iterations\n";
    }
}

// The step is x + beta r - (dX + beta dR) gamma with gamma the least-
// squares solution, checked against an independent QR solve of the
// stored differences
TEST(AndersonAcceleration, StepMatchesDirectLeastSquares)
{
    const int n = 12, depth = 3;
    const double beta = 0.5;
    const LinearProblem lp(n, 3, 0.8);

    AndersonAcceleration aa(params(depth, beta));
    std::vector<Vec> xs, rs;
    Vec x = lp.x0;
    for (int k = 0; k < 8; ++k)
    {
        const Vec g = lp.G(x);
        const Vec r = g - x;
        xs.push_back(x);
        rs.push_back(r);

        const Vec xNext = step(aa, x, g);

        const int c = std::min<int>(depth, k);
        ASSERT_EQ(aa.nColumns(), c) << "iteration " << k;
        ASSERT_EQ(aa.gamma().size(), c);
        Mat dX(n, c), dR(n, c);
        for (int j = 0; j < c; ++j)
        {
            const int i = k - c + j;    // oldest first
            dX.col(j) = xs[i + 1] - xs[i];
            dR.col(j) = rs[i + 1] - rs[i];
        }
        Vec expected = x + beta*r;
        if (c > 0)
        {
            const Vec gamma = dR.colPivHouseholderQr().solve(r);
            EXPECT_LT((aa.gamma() - gamma).norm(), 1e-9*(1 + gamma.norm()))
                << "iteration " << k;
            expected -= (dX + beta*dR)*gamma;
        }
        EXPECT_LT((xNext - expected).norm(), 1e-12*expected.norm())
            << "iteration " << k;
        EXPECT_NEAR(aa.residualNorm(), r.norm(), 1e-14*r.norm());
        x = xNext;
    }
    EXPECT_EQ(aa.nDropped(), 0);
    EXPECT_EQ(aa.nSkipped(), 0);
}


// * * * * * * * * * * * * * * * Nonlinear maps * * * * * * * * * * * * * //

TEST(AndersonAcceleration, CosineConvergesToDottieNumber)
{
    const int n = 10;
    std::mt19937 gen(11);
    const Vec x0 = randomVector(n, gen);
    const Vec xStar = Vec::Constant(n, dottie);

    const Outcome p = plain(cosine, x0, xStar, 1e-12, 1000);
    const Outcome a = accelerate(params(3, 1.0), cosine, x0, xStar, 1e-12, 1000);
    ASSERT_GT(p.iterations, 0);
    ASSERT_GT(a.iterations, 0) << "error " << a.error;
    std::cout << "plain " << p.iterations << ", Anderson(3) " << a.iterations << '\n';
    EXPECT_LT(2*a.iterations, p.iterations);
}

// Coupled and nonlinear, with the diverging -1.2 mode in its Jacobian:
// G(x) = x* + A e + 0.2 (e o e) + 0.1 sin(B e), e = x - x*
TEST(AndersonAcceleration, NonlinearSystemWithDivergingModeConverges)
{
    const int n = 15;
    std::mt19937 gen(5);
    const Mat A = withDivergingMode(n, 0.8, gen);
    Mat B(n, n);
    for (int j = 0; j < n; ++j)
    {
        B.col(j) = randomVector(n, gen)/n;
    }
    const Vec xStar = randomVector(n, gen);
    const MapFn G = [=](const Vec& x) -> Vec
    {
        const Vec e = x - xStar;
        return xStar + A*e + 0.2*e.cwiseProduct(e)
             + 0.1*(B*e).array().sin().matrix();
    };
    const Vec x0 = xStar + 0.2*randomVector(n, gen);

    for (const double beta : {1.0, 0.5})
    {
        const Outcome a = accelerate(params(5, beta), G, x0, xStar, 1e-10, 300);
        EXPECT_TRUE(a.finite);
        EXPECT_GT(a.iterations, 0) << "beta " << beta << ": error " << a.error;
        std::cout << "[ beta " << beta << " ] " << a.iterations << " iterations\n";
    }
}


// * * * * * * * * * * * * * * * * Parallel  * * * * * * * * * * * * * * * //

TEST(AndersonAcceleration, SlicesGiveTheSerialIterates)
{
    const LinearProblem lp(20, 20240611, 0.95);
    const auto G = [&lp](const Vec& x, int) { return lp.G(x); };

    const std::vector<std::vector<int>> splits =
    {
        {10, 10}, {7, 13}, {0, 20}, {20, 0}, {6, 0, 14}
    };
    for (const double beta : {1.0, 0.5})
    {
        for (const auto& split : splits)
        {
            const ParallelOutcome o =
                parallelDifference(split, params(5, beta), G, lp.x0, lp.xStar, 40);
            std::cout << "[ beta " << beta << ", " << split.size()
                      << " slices, first " << split[0] << " ] max difference "
                      << o.maxDiff << '\n';
            EXPECT_LT(o.maxDiff, 1e-12) << "beta " << beta << ", first slice " << split[0];
            EXPECT_EQ(o.maxColumns, 5);
        }
    }
}

// The same with column dropping, skipping and a restart on the way: the
// decisions are taken on reduced values, so slices agree on them
TEST(AndersonAcceleration, SlicesAgreeThroughDropsAndRestarts)
{
    // Three unknowns, depth 8: columns beyond the third are dependent.
    // After 8 correctors the map changes (a load jump), which the growth
    // guard must catch; the new fixed point solves x = cos(x) + 0.5.
    const int n = 3;
    const auto G = [](const Vec& x, const int k) -> Vec
    {
        return (x.array().cos() + (k < 8 ? 0.0 : 0.5)).matrix();
    };
    const Vec xStar = Vec::Constant(n, 1.0);   // only a scale for the error
    const Vec x0 = (Vec(n) << 0.1, -0.5, 1.0).finished();

    AndersonAcceleration::Parameters p = params(8, 0.7);
    p.restartGrowth = 2;
    for (const auto& split : std::vector<std::vector<int>>{{1, 2}, {0, 3}, {2, 0, 1}})
    {
        const ParallelOutcome o = parallelDifference(split, p, G, x0, xStar, 30);
        std::cout << "[ first slice " << split[0] << " ] max difference "
                  << o.maxDiff << ", dropped " << o.dropped << ", skipped "
                  << o.skipped << ", restarts " << o.restarts << '\n';
        EXPECT_LT(o.maxDiff, 1e-12) << "first slice " << split[0];
        EXPECT_GT(o.dropped, 0);
        EXPECT_GT(o.restarts, 0);
    }
}


// * * * * * * * * * * * * * * * Degenerate input  * * * * * * * * * * * * //

TEST(AndersonAcceleration, ZeroResidualReturnsXUnchanged)
{
    const int n = 6;
    std::mt19937 gen(1);
    const Vec x = randomVector(n, gen);

    // First call
    AndersonAcceleration aa(params(3, 0.5));
    EXPECT_TRUE(step(aa, x, x) == x);
    EXPECT_EQ(aa.residualNorm(), 0.0);

    // With a history: a few steps of a contraction, then a fixed point
    const Mat A = randomContraction(n, 0.5, gen);
    iterate(aa, linearMap(A, x), randomVector(n, gen), 4);
    ASSERT_GT(aa.nColumns(), 0);
    const Vec z = randomVector(n, gen);
    EXPECT_TRUE(step(aa, z, z) == z);
    EXPECT_TRUE(aa.gamma().allFinite());
    EXPECT_EQ(aa.gamma().norm(), 0.0);
    EXPECT_EQ(aa.residualNorm(), 0.0);
}

TEST(AndersonAcceleration, RepeatedIteratesAreSkipped)
{
    const int n = 5;
    std::mt19937 gen(2);
    const Vec x = randomVector(n, gen);
    const Vec g = randomVector(n, gen);
    const double beta = 0.5;

    AndersonAcceleration aa(params(3, beta));
    for (int k = 0; k < 6; ++k)
    {
        const Vec xNext = step(aa, x, g);
        ASSERT_TRUE(xNext.allFinite()) << "call " << k;
        // Nothing to extrapolate from: the plain relaxed step every time
        EXPECT_LT((xNext - (x + beta*(g - x))).norm(), 1e-15*x.norm());
        EXPECT_EQ(aa.nColumns(), 0);
    }
    EXPECT_EQ(aa.nSkipped(), 5);

    // A repeated iterate in the middle of a real history adds nothing
    const Mat A = randomContraction(n, 0.6, gen);
    const MapFn G = linearMap(A, x);
    aa.reset();
    const Vec y = iterate(aa, G, g, 3);
    const int columns = aa.nColumns();
    ASSERT_EQ(columns, 2);
    const Vec gy = G(y);
    step(aa, y, gy);
    const Vec xNext = step(aa, y, gy);
    EXPECT_TRUE(xNext.allFinite());
    EXPECT_TRUE(aa.gamma().allFinite());
    EXPECT_EQ(aa.nColumns(), columns + 1);
    EXPECT_EQ(aa.nSkipped(), 6);
}

TEST(AndersonAcceleration, DependentColumnsAreDroppedNotInverted)
{
    // More columns than unknowns: the normal matrix must become singular
    // and the oldest columns go
    const int n = 3;
    const Vec xStar = Vec::Constant(n, dottie);

    AndersonAcceleration aa(params(10, 1.0));
    Vec x = (Vec(n) << 0.1, -0.5, 1.0).finished();
    for (int k = 0; k < 30; ++k)
    {
        x = step(aa, x, cosine(x));
        ASSERT_TRUE(x.allFinite()) << "iteration " << k;
        ASSERT_TRUE(aa.gamma().allFinite()) << "iteration " << k;
        EXPECT_LE(aa.nColumns(), n);
    }
    EXPECT_GT(aa.nDropped() + aa.nSkipped(), 0);
    EXPECT_LT(relError(x, xStar), 1e-12);
}

// Every combination of depth, beta and scale: finite iterates and the
// same number of iterations at every scale (the method and its
// thresholds are scale-invariant, so an absolute tolerance would show)
TEST(AndersonAcceleration, DegenerateSweepStaysFiniteAndScaleInvariant)
{
    const LinearProblem lp(20, 20240611, 0.95);

    int checked = 0;
    for (const int depth : {1, 2, 5})
    {
        for (const double beta : {1.0, 0.5})
        {
            int reference = -2;
            for (const double scale : {1.0, 1e-12, 1e12})
            {
                SCOPED_TRACE
                (
                    ::testing::Message() << "depth " << depth << " beta "
                        << beta << " scale " << scale
                );
                const Vec xStar = scale*lp.xStar;
                AndersonAcceleration aa(params(depth, beta));
                const Outcome run =
                    accelerate(aa, linearMap(lp.A, xStar), scale*lp.x0, xStar, 1e-10, 5000);
                ASSERT_TRUE(run.finite);
                EXPECT_GT(run.iterations, 0);
                EXPECT_TRUE(aa.gamma().allFinite());
                EXPECT_TRUE(std::isfinite(aa.residualNorm()));
                if (scale == 1.0)
                {
                    reference = run.iterations;
                }
                else
                {
                    EXPECT_NEAR(run.iterations, reference, 1);
                }
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 3*2*3);
}

TEST(AndersonAcceleration, EmptySliceInSerialIsHarmless)
{
    AndersonAcceleration aa(params(2, 1.0));
    for (int k = 0; k < 3; ++k)
    {
        aa.update(nullptr, nullptr, nullptr, 0);
        EXPECT_EQ(aa.residualNorm(), 0.0);
        EXPECT_EQ(aa.nColumns(), 0);
    }
    std::vector<double> e, eNext;
    aa.update(e, e, eNext);
    EXPECT_TRUE(eNext.empty());
}

TEST(AndersonAcceleration, NonFiniteResidualRestartsCleanly)
{
    const LinearProblem lp(8, 9, 0.9);

    AndersonAcceleration aa(params(4, 1.0));
    const Vec x = iterate(aa, lp.G, lp.x0, 4);
    ASSERT_GT(aa.nColumns(), 0);

    Vec bad = lp.G(x);
    bad(3) = std::numeric_limits<double>::quiet_NaN();
    step(aa, x, bad);
    EXPECT_FALSE(std::isfinite(aa.residualNorm()));
    EXPECT_EQ(aa.nColumns(), 0);
    EXPECT_EQ(aa.nRestarts(), 1);

    // The caller throws the bad iterate away and carries on from x: no
    // NaN may have been kept in the history
    const Outcome run = accelerate(aa, lp.G, x, lp.xStar, 1e-10, 200);
    EXPECT_TRUE(run.finite);
    EXPECT_GT(run.iterations, 0);
}

TEST(AndersonAcceleration, InPlaceUpdateEqualsSeparateOutput)
{
    const int n = 9;
    const LinearProblem lp(n, 4, 0.9);

    AndersonAcceleration a(params(3, 0.5)), b(params(3, 0.5));
    std::vector<double> xa(lp.x0.data(), lp.x0.data() + n), xb = xa;
    for (int k = 0; k < 6; ++k)
    {
        const Vec ga = lp.G(Eigen::Map<Vec>(xa.data(), n));
        std::vector<double> gav(ga.data(), ga.data() + n), next;
        a.update(xa, gav, next);
        xa = next;

        const Vec gb = lp.G(Eigen::Map<Vec>(xb.data(), n));
        std::vector<double> gbv(gb.data(), gb.data() + n);
        b.update(xb, gbv, xb);     // into x itself
        ASSERT_EQ(xa, xb) << "iteration " << k;

        std::vector<double> xc = xb, gc = gbv;
        AndersonAcceleration c(params(3, 0.5));
        c.update(xc, gc, gc);      // into G(x)
        EXPECT_NEAR(gc[0], xc[0] + 0.5*(gbv[0] - xc[0]), 1e-15);
    }

    std::vector<double> shortG(n - 1), out;
    EXPECT_THROW(a.update(xa, shortG, out), std::invalid_argument);
}

TEST(AndersonAcceleration, ResetAndSizeChangeStartAfresh)
{
    const int n = 6;
    LinearProblem lp(n, 6, 0.9);

    AndersonAcceleration aa(params(3, 1.0));
    const Vec x = iterate(aa, lp.G, lp.x0, 4);
    ASSERT_EQ(aa.nColumns(), 3);

    aa.reset();
    EXPECT_EQ(aa.nColumns(), 0);
    EXPECT_EQ(aa.gamma().size(), 0);
    {
        const Vec g = lp.G(x);
        EXPECT_TRUE(step(aa, x, g) == x + (g - x));
        EXPECT_EQ(aa.nColumns(), 0);
    }

    // A different slice size (topology change) without reset: history
    // dropped, plain step, no out-of-range access
    const Vec y = randomVector(n + 2, lp.gen), gy = randomVector(n + 2, lp.gen);
    Vec yNext = step(aa, y, gy);
    EXPECT_EQ(aa.nColumns(), 0);
    EXPECT_EQ(aa.nRestarts(), 1);
    EXPECT_TRUE(yNext == y + (gy - y));
    aa.update(yNext.data(), gy.data(), yNext.data(), n + 2);
    EXPECT_EQ(aa.nColumns(), 1);
}

// An active set that changed: clearColumns() keeps the last iterate, so
// the next update is the one-column secant through the change (checked
// against the formula), where reset() gives a plain step; on a scalar
// linear map that secant lands on the fixed point
TEST(AndersonAcceleration, ClearColumnsKeepsTheIterateForOneSecant)
{
    const int n = 8;
    LinearProblem lp(n, 11, 0.9);

    AndersonAcceleration aa(params(4, 1.0));
    const Vec xPrev = iterate(aa, lp.G, lp.x0, 5);
    ASSERT_GT(aa.nColumns(), 1);
    // The last update stored xPrev's predecessor; one more stores xPrev
    const Vec rPrev = lp.G(xPrev) - xPrev;
    const Vec x = step(aa, xPrev, lp.G(xPrev));

    aa.clearColumns();
    EXPECT_EQ(aa.nColumns(), 0);
    EXPECT_EQ(aa.gamma().size(), 0);

    const Vec r = lp.G(x) - x;
    const Vec xNext = step(aa, x, lp.G(x));
    ASSERT_EQ(aa.nColumns(), 1);
    const Vec dr = r - rPrev, dx = x - xPrev;
    const double gamma = dr.dot(r)/dr.dot(dr);
    EXPECT_NEAR(aa.gamma()(0), gamma, 1e-12*std::abs(gamma));
    EXPECT_LT((xNext - (x + r - (dx + dr)*gamma)).norm(), 1e-12*x.norm());

    // Scalar: after clearColumns the secant is exact, after reset plain
    const auto G1 = [](const double y) { return 0.95*y + 1.0; };
    const double yStar = 20.0;
    for (const bool clear : {true, false})
    {
        AndersonAcceleration a1(params(3, 1.0));
        Vec y(1), g(1);
        y << 3.0;
        // One plain step: no column yet, but a stored iterate
        g << G1(y(0));
        y = step(a1, y, g);
        ASSERT_EQ(a1.nColumns(), 0);
        clear ? a1.clearColumns() : a1.reset();
        g << G1(y(0));
        const Vec yNext = step(a1, y, g);
        if (clear)
        {
            EXPECT_NEAR(yNext(0), yStar, 1e-10);
        }
        else
        {
            EXPECT_EQ(yNext(0), g(0));
        }
    }
}

// A load step in which the map changes under the iteration (an active
// set switching): the residual jumps, the guard restarts
TEST(AndersonAcceleration, ResidualGrowthRestartsWhenAsked)
{
    const int n = 10;
    std::mt19937 gen(8);
    const Mat A = randomContraction(n, 0.9, gen);
    const Vec x1 = randomVector(n, gen);
    const Vec x2 = x1 + 10*randomVector(n, gen);

    for (const double growth : {std::numeric_limits<double>::infinity(), 10.0})
    {
        AndersonAcceleration::Parameters p = params(4, 1.0);
        p.restartGrowth = growth;
        AndersonAcceleration aa(p);

        const Vec x = iterate(aa, linearMap(A, x1), randomVector(n, gen), 6);
        ASSERT_GT(aa.nColumns(), 0);
        const Vec g = linearMap(A, x2)(x);
        const Vec xNext = step(aa, x, g);
        if (std::isinf(growth))
        {
            EXPECT_EQ(aa.nRestarts(), 0);
            EXPECT_GT(aa.nColumns(), 0);
        }
        else
        {
            EXPECT_EQ(aa.nRestarts(), 1);
            EXPECT_EQ(aa.nColumns(), 0);
            EXPECT_TRUE(xNext == x + (g - x));
        }
        // Either way it then converges to the new fixed point
        const Outcome run = accelerate(aa, linearMap(A, x2), xNext, x2, 1e-10, 300);
        EXPECT_GT(run.iterations, 0) << "growth " << growth;
    }
}

TEST(AndersonAcceleration, RegularisationDampsGamma)
{
    const LinearProblem lp(10, 10, 0.9);

    double norms[2];
    int i = 0;
    for (const double reg : {0.0, 1e8})
    {
        AndersonAcceleration::Parameters p = params(3, 1.0);
        p.regularisation = reg;
        AndersonAcceleration aa(p);
        iterate(aa, lp.G, lp.x0, 5);
        ASSERT_EQ(aa.nColumns(), 3);
        norms[i++] = aa.gamma().norm();
    }
    EXPECT_GT(norms[0], 1e-3);
    EXPECT_LT(norms[1], 1e-6*norms[0]);
}


// * * * * * * * * * * * * * * * Bad parameters  * * * * * * * * * * * * * //

TEST(AndersonAcceleration, InvalidParametersThrowNamingTheRange)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();

    const auto message = [](const AndersonAcceleration::Parameters& p) -> std::string
    {
        try
        {
            AndersonAcceleration aa(p);
        }
        catch (const std::invalid_argument& e)
        {
            return e.what();
        }
        return "";
    };

    for (const int depth : {0, -1})
    {
        const std::string m = message(params(depth, 1.0));
        EXPECT_NE(m.find("depth m must be >= 1"), std::string::npos) << m;
        EXPECT_NE(m.find(std::to_string(depth)), std::string::npos) << m;
    }
    for (const double beta : {0.0, -0.5, 1.5, nan, inf})
    {
        const std::string m = message(params(5, beta));
        EXPECT_NE(m.find("beta must be in (0, 1]"), std::string::npos)
            << "beta " << beta << ": " << m;
    }
    EXPECT_THROW(AndersonAcceleration(0, 1.0), std::invalid_argument);
    EXPECT_THROW(AndersonAcceleration(3, 1.0000001), std::invalid_argument);

    AndersonAcceleration::Parameters p;
    p.maxCondition = 1;
    EXPECT_NE(message(p).find("maxCondition must be > 1"), std::string::npos);
    p.maxCondition = nan;
    EXPECT_NE(message(p).find("maxCondition"), std::string::npos);

    p = AndersonAcceleration::Parameters();
    p.regularisation = -1e-3;
    EXPECT_NE(message(p).find("regularisation must be finite and >= 0"), std::string::npos);
    p.regularisation = inf;
    EXPECT_NE(message(p).find("regularisation"), std::string::npos);

    p = AndersonAcceleration::Parameters();
    p.restartGrowth = 0.5;
    EXPECT_NE(message(p).find("restartGrowth must be >= 1"), std::string::npos);

    // The edges of the valid ranges are accepted
    EXPECT_NO_THROW(AndersonAcceleration(1, 1.0));
    EXPECT_NO_THROW(AndersonAcceleration(1, 1e-9));
    p = AndersonAcceleration::Parameters();
    p.maxCondition = inf;
    p.restartGrowth = 1;
    EXPECT_NO_THROW(AndersonAcceleration aa(p));
    EXPECT_EQ(message(AndersonAcceleration::Parameters()), "");
}
