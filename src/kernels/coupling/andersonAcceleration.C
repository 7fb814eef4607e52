/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "andersonAcceleration.H"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace c4f
{
namespace coupling
{

namespace
{

// Below this fraction of the residuals it is formed from, a difference
// r_k - r_{k-1} is cancellation noise (1e-13 is a few hundred ulps)
constexpr double noiseLevel = 1e-13;

std::string number(const double v)
{
    std::ostringstream os;
    os.precision(17);
    os << v;
    return os.str();
}

[[noreturn]] void badParameter(const std::string& what, const double got)
{
    throw std::invalid_argument
    (
        "AndersonAcceleration: " + what + ", got " + number(got)
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

AndersonAcceleration::AndersonAcceleration
(
    const Parameters& p,
    Reduction reduce
)
:
    params_(p),
    reduce_(std::move(reduce))
{
    check(params_);

    const int slots = params_.depth + 1;
    gram_.setZero(slots, slots);
    dX_.resize(0, slots);
    dR_.resize(0, slots);
    slots_.reserve(slots);
}


AndersonAcceleration::AndersonAcceleration
(
    const int depth,
    const double beta,
    Reduction reduce
)
:
    AndersonAcceleration
    (
        [&]
        {
            Parameters p;
            p.depth = depth;
            p.beta = beta;
            return p;
        }(),
        std::move(reduce)
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void AndersonAcceleration::check(const Parameters& p)
{
    if (p.depth < 1)
    {
        badParameter
        (
            "depth m must be >= 1 (the number of difference columns kept)",
            p.depth
        );
    }
    // The comparisons are written so that NaN fails them
    if (!(p.beta > 0 && p.beta <= 1))
    {
        badParameter("beta must be in (0, 1] (the mixing factor)", p.beta);
    }
    if (!(p.maxCondition > 1))
    {
        badParameter
        (
            "maxCondition must be > 1 (inf: never drop columns)",
            p.maxCondition
        );
    }
    if (!(p.regularisation >= 0) || !std::isfinite(p.regularisation))
    {
        badParameter
        (
            "regularisation must be finite and >= 0",
            p.regularisation
        );
    }
    if (!(p.restartGrowth >= 1))
    {
        badParameter
        (
            "restartGrowth must be >= 1 (inf: never restart)",
            p.restartGrowth
        );
    }
}


void AndersonAcceleration::clearHistory()
{
    slots_.clear();
    gamma_.resize(0);
}


void AndersonAcceleration::reset()
{
    clearHistory();
    hasPrev_ = false;
}


void AndersonAcceleration::clearColumns()
{
    clearHistory();
}


int AndersonAcceleration::freeSlot() const
{
    for (int s = 0; s <= params_.depth; ++s)
    {
        if (std::find(slots_.begin(), slots_.end(), s) == slots_.end())
        {
            return s;
        }
    }
    // Unreachable: at most depth of the depth + 1 slots are in use
    return params_.depth;
}


void AndersonAcceleration::update
(
    const std::vector<double>& x,
    const std::vector<double>& g,
    std::vector<double>& xNext
)
{
    if (g.size() != x.size())
    {
        throw std::invalid_argument
        (
            "AndersonAcceleration::update: x has "
          + std::to_string(x.size()) + " values but G(x) has "
          + std::to_string(g.size())
        );
    }
    // Resizing first keeps xNext's data valid when it is x or g itself
    xNext.resize(x.size());
    update(x.data(), g.data(), xNext.data(), x.size());
}


void AndersonAcceleration::update
(
    const double* x,
    const double* g,
    double* xNext,
    const std::size_t n
)
{
    const Eigen::Index nn = static_cast<Eigen::Index>(n);

    // Copies first: xNext may alias x or g, and x, r become the
    // previous iterate of the next call
    x_ = Eigen::Map<const Eigen::VectorXd>(x, nn);
    r_ = Eigen::Map<const Eigen::VectorXd>(g, nn) - x_;

    // hasPrev_ and slots_ are the same on every processor (they change
    // only on reduced values), so the buffer layout is too
    const bool candidate = hasPrev_;
    const bool sizeChanged = hasPrev_ && n != n_;
    const int c = nColumns();

    // Layout: |r|^2, size-change flag, then with a candidate column dr:
    // dr.dr, dr.dR_j (c), dR_j.r (c), dr.r
    const int nBuf = 2 + (candidate ? 2 + 2*c : 0);
    buffer_.assign(nBuf, 0.0);

    buffer_[0] = r_.squaredNorm();
    buffer_[1] = sizeChanged ? 1.0 : 0.0;

    int s = -1;
    if (candidate)
    {
        s = freeSlot();
        // A processor whose slice changed size has no matching history:
        // it contributes zeros, and the flag makes everyone discard it
        if (!sizeChanged)
        {
            dR_.col(s) = r_ - rPrev_;
            dX_.col(s) = x_ - xPrev_;

            const auto dr = dR_.col(s);
            buffer_[2] = dr.squaredNorm();
            for (int j = 0; j < c; ++j)
            {
                buffer_[3 + j] = dr.dot(dR_.col(slots_[j]));
                buffer_[3 + c + j] = dR_.col(slots_[j]).dot(r_);
            }
            buffer_[3 + 2*c] = dr.dot(r_);
        }
    }

    // The one collective call of the update, made on every processor
    // whatever its n, so that a parallel run cannot hang here
    if (reduce_)
    {
        reduce_(buffer_.data(), nBuf);
    }

    const double rr = buffer_[0];
    residualNorm_ = std::sqrt(rr);

    Eigen::Map<Eigen::VectorXd> xn(xNext, nn);

    const auto plainStep = [&]()
    {
        gamma_.resize(0);
        xn = x_ + params_.beta*r_;
    };

    bool storePrev = true;

    if (buffer_[1] > 0)
    {
        // Somebody's slice changed: no column can be trusted anywhere
        clearHistory();
        ++nRestarts_;
        plainStep();
    }
    else if (!std::isfinite(rr))
    {
        // G produced NaN or Inf somewhere. Keep none of it, so that a
        // later finite iterate starts clean; the plain step passes the
        // NaN on to the caller's residual check
        clearHistory();
        ++nRestarts_;
        plainStep();
        storePrev = false;
    }
    else if
    (
        c > 0
     && std::isfinite(params_.restartGrowth)
     && rr > params_.restartGrowth*params_.restartGrowth*rrPrev_
    )
    {
        // The last accelerated step made things worse: the secants
        // describe a G that is no longer there (an active set switched,
        // say). The new difference spans that switch, so it goes too.
        clearHistory();
        ++nRestarts_;
        plainStep();
    }
    else
    {
        // Right-hand side dR^T r by slot
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(params_.depth + 1);
        for (int j = 0; j < c; ++j)
        {
            rhs(slots_[j]) = buffer_[3 + c + j];
        }

        if (candidate)
        {
            const double drdr = buffer_[2];
            const double scale = std::max(rr, rrPrev_);
            if (drdr > noiseLevel*noiseLevel*scale)
            {
                gram_(s, s) = drdr;
                for (int j = 0; j < c; ++j)
                {
                    gram_(s, slots_[j]) = buffer_[3 + j];
                    gram_(slots_[j], s) = buffer_[3 + j];
                }
                rhs(s) = buffer_[3 + 2*c];
                slots_.push_back(s);
                if (nColumns() > params_.depth)
                {
                    slots_.erase(slots_.begin());
                }
            }
            else
            {
                ++nSkipped_;
            }
        }

        // Unit-diagonal scaling D^{-1/2} M D^{-1/2}: the condition test
        // then sees dependence, not the spread of column sizes. Done
        // even at r = 0, so that the history never holds a dependent set.
        Eigen::MatrixXd A;
        Eigen::VectorXd d;
        while (!slots_.empty())
        {
            const int m = nColumns();
            d.resize(m);
            for (int i = 0; i < m; ++i)
            {
                d(i) = std::sqrt(gram_(slots_[i], slots_[i]));
            }
            A.resize(m, m);
            for (int i = 0; i < m; ++i)
            {
                for (int j = 0; j < m; ++j)
                {
                    A(i, j) = gram_(slots_[i], slots_[j])/(d(i)*d(j));
                }
                A(i, i) = 1 + params_.regularisation;
            }
            if (m == 1)
            {
                break;
            }
            const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig
            (
                A,
                Eigen::EigenvaluesOnly
            );
            const double lMin = eig.eigenvalues()(0);
            const double lMax = eig.eigenvalues()(m - 1);
            if (lMin > 0 && lMax <= params_.maxCondition*lMin)
            {
                break;
            }
            // The oldest column is the one the newer secants have made
            // redundant (and the least local one)
            slots_.erase(slots_.begin());
            ++nDropped_;
        }

        const int m = nColumns();
        if (rr == 0 || m == 0)
        {
            // Converged exactly (gamma = 0), or nothing to extrapolate
            // from: the plain step
            gamma_.setZero(m);
            xn = x_ + params_.beta*r_;
        }
        else
        {
            Eigen::VectorXd b(m);
            for (int i = 0; i < m; ++i)
            {
                b(i) = rhs(slots_[i])/d(i);
            }
            gamma_ = A.ldlt().solve(b).cwiseQuotient(d);

            if (!gamma_.allFinite())
            {
                // Cannot happen for a bounded condition number; if it
                // does, every processor sees it (same data, same solve)
                clearHistory();
                ++nRestarts_;
                plainStep();
            }
            else
            {
                xn = x_ + params_.beta*r_;
                for (int i = 0; i < m; ++i)
                {
                    const int si = slots_[i];
                    xn -= gamma_(i)*(dX_.col(si) + params_.beta*dR_.col(si));
                }
            }
        }

        if (rr == 0)
        {
            // Exactly unchanged: |r|^2 can also underflow to 0 for a
            // residual of order 1e-170 that is not zero bit for bit
            xn = x_;
        }
    }

    if (!storePrev)
    {
        hasPrev_ = false;
        return;
    }

    if (dR_.rows() != nn)
    {
        // First call, or the slice changed size (history cleared above)
        dR_.setZero(nn, params_.depth + 1);
        dX_.setZero(nn, params_.depth + 1);
    }
    xPrev_.swap(x_);
    rPrev_.swap(r_);
    rrPrev_ = rr;
    n_ = n;
    hasPrev_ = true;
}

} // End namespace coupling
} // End namespace c4f
