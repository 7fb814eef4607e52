/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "gmres.H"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>
#include <string>

namespace c4f
{
namespace coupling
{

Gmres::Gmres(const GmresParameters& p, Reduction reduce)
:
    params_(p),
    reduce_(std::move(reduce))
{
    check(p);
}


void Gmres::check(const GmresParameters& p)
{
    if (p.maxIterations < 1)
    {
        throw std::invalid_argument
        (
            "maxIterations = " + std::to_string(p.maxIterations)
          + ": it must be an integer >= 1"
        );
    }
    if (!(p.relativeTolerance > 0 && p.relativeTolerance < 1))
    {
        throw std::invalid_argument
        (
            "relativeTolerance = " + std::to_string(p.relativeTolerance)
          + ": it must lie in (0, 1)"
        );
    }
}


double Gmres::dot(const Vector& a, const Vector& b) const
{
    double s = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        s += a[i]*b[i];
    }
    if (reduce_)
    {
        reduce_(&s, 1);
    }
    return s;
}


GmresResult Gmres::solve
(
    const Operator& A,
    const Vector& b,
    Vector& x
) const
{
    return solve(A, b, x, params_.relativeTolerance);
}


GmresResult Gmres::solve
(
    const Operator& A,
    const Vector& b,
    Vector& x,
    double relativeTolerance
) const
{
    if (!(relativeTolerance > 0 && relativeTolerance < 1))
    {
        throw std::invalid_argument
        (
            "Gmres::solve: relativeTolerance = "
          + std::to_string(relativeTolerance) + ": it must lie in (0, 1)"
        );
    }
    const std::size_t n = b.size();
    const int m = params_.maxIterations;

    x.assign(n, 0.0);

    GmresResult result;
    const double beta = std::sqrt(dot(b, b));
    result.initialNorm = beta;
    result.residualNorm = beta;
    if (beta == 0 || !std::isfinite(beta))
    {
        result.converged = (beta == 0);
        return result;
    }

    // The Krylov basis, H (m+1 x m) with its Givens rotations applied, and
    // the rotated right-hand side beta e1
    std::vector<Vector> V(1, Vector(n));
    for (std::size_t i = 0; i < n; ++i)
    {
        V[0][i] = b[i]/beta;
    }
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(m + 1, m);
    Eigen::VectorXd cs = Eigen::VectorXd::Zero(m);
    Eigen::VectorXd sn = Eigen::VectorXd::Zero(m);
    Eigen::VectorXd s = Eigen::VectorXd::Zero(m + 1);
    s(0) = beta;

    const double target = relativeTolerance*beta;
    int k = 0;
    Vector w;

    for (; k < m; ++k)
    {
        A(V[k], w);
        ++result.iterations;
        if (w.size() != n)
        {
            throw std::invalid_argument
            (
                "Gmres::solve: the operator returned "
              + std::to_string(w.size()) + " values for "
              + std::to_string(n)
            );
        }

        const double normW0 = std::sqrt(dot(w, w));
        if (!std::isfinite(normW0))
        {
            break;
        }

        // Modified Gram-Schmidt, repeated once when the projections took
        // most of the vector
        for (int pass = 0; pass < 2; ++pass)
        {
            for (int j = 0; j <= k; ++j)
            {
                const double h = dot(w, V[j]);
                H(j, k) += h;
                for (std::size_t i = 0; i < n; ++i)
                {
                    w[i] -= h*V[j][i];
                }
            }
            const double normW = std::sqrt(dot(w, w));
            H(k + 1, k) = normW;
            if (normW > 0.5*normW0)
            {
                break;
            }
        }

        // The rotations of the earlier columns, then this column's own
        for (int j = 0; j < k; ++j)
        {
            const double t = cs(j)*H(j, k) + sn(j)*H(j + 1, k);
            H(j + 1, k) = -sn(j)*H(j, k) + cs(j)*H(j + 1, k);
            H(j, k) = t;
        }
        // What is left of A v_k after the projections, relative to A v_k:
        // below round-off it is zero (a breakdown)
        const double roundOff = 1e-13*normW0;
        if (H(k + 1, k) <= roundOff)
        {
            H(k + 1, k) = 0;
        }
        const double hkk = H(k, k);
        const double hk1 = H(k + 1, k);
        const double r = std::hypot(hkk, hk1);
        if (!(r > roundOff))
        {
            // A v_k in the span of the earlier A v_j: A is singular on the
            // basis and the least squares cannot improve; stop with the
            // columns before this one
            break;
        }
        const bool breakdown = !(hk1 > 0);
        cs(k) = hkk/r;
        sn(k) = hk1/r;
        H(k, k) = r;
        H(k + 1, k) = 0;
        s(k + 1) = -sn(k)*s(k);
        s(k) = cs(k)*s(k);

        result.residualNorm = std::abs(s(k + 1));

        if (breakdown || result.residualNorm <= target)
        {
            result.converged = true;
            ++k;
            break;
        }

        V.emplace_back(n);
        for (std::size_t i = 0; i < n; ++i)
        {
            V[k + 1][i] = w[i]/hk1;
        }
    }

    // x = V_k y with R_k y = s_k (R the rotated H, whose pivots are > 0)
    const int kUsed = k;
    if (kUsed == 0)
    {
        return result;
    }
    const Eigen::VectorXd y =
        H.topLeftCorner(kUsed, kUsed).triangularView<Eigen::Upper>()
       .solve(s.head(kUsed));

    for (int j = 0; j < kUsed; ++j)
    {
        for (std::size_t i = 0; i < n; ++i)
        {
            x[i] += y(j)*V[j][i];
        }
    }

    return result;
}

} // End namespace coupling
} // End namespace c4f
