/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "nagataPatch.H"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace c4f
{
namespace search
{

Eigen::Vector3d nagataEdgeCoefficient
(
    const Eigen::Vector3d& x0,
    const Eigen::Vector3d& x1,
    const Eigen::Vector3d& n0,
    const Eigen::Vector3d& n1
)
{
    const Eigen::Vector3d d(x1 - x0);
    const double k = n0.dot(n1);
    const double det = 1 - k*k;
    if (!(det > 1e-12))
    {
        return Eigen::Vector3d::Zero();
    }
    const double r0 = n0.dot(d);
    const double r1 = -n1.dot(d);
    const double a = (r0 - k*r1)/det;
    const double b = (r1 - k*r0)/det;
    Eigen::Vector3d c(a*n0 + b*n1);

    // A parabola cannot turn more than its end normals do: past |d| phi
    // (phi the angle between n0 and n1; an arc has |c| = |d| tan(phi/2))
    // the two tangency conditions are inconsistent with the chord
    const double phi = std::atan2(n0.cross(n1).norm(), k);
    const double cap = d.norm()*std::min(1.0, phi);
    const double mag = c.norm();
    if (mag > cap)
    {
        c *= cap/mag;
    }
    return c;
}


NagataPatch::NagataPatch
(
    const std::vector<Eigen::Vector3d>& x,
    const std::vector<Eigen::Vector3d>& n
)
:
    n_(0),
    bulge_(0)
{
    for (Eigen::Vector3d& c : c_)
    {
        c.setZero();
    }

    if (x.size() != n.size() || (x.size() != 3 && x.size() != 4))
    {
        return;
    }

    if (x.size() == 4)
    {
        // x00 = x[0], x10 = x[1], x11 = x[2], x01 = x[3]
        const Eigen::Vector3d c1(nagataEdgeCoefficient(x[0], x[1], n[0], n[1]));
        const Eigen::Vector3d c2(nagataEdgeCoefficient(x[1], x[2], n[1], n[2]));
        const Eigen::Vector3d c3(nagataEdgeCoefficient(x[3], x[2], n[3], n[2]));
        const Eigen::Vector3d c4(nagataEdgeCoefficient(x[0], x[3], n[0], n[3]));
        c_[0] = x[0];
        c_[1] = x[1] - x[0] - c1;
        c_[2] = x[3] - x[0] - c4;
        c_[3] = x[0] - x[1] + x[2] - x[3] + c1 - c2 - c3 + c4;
        c_[4] = c1;
        c_[5] = c4;
        c_[6] = c3 - c1;
        c_[7] = c2 - c4;
        bulge_ = 0.25*(c1.norm() + c2.norm() + c3.norm() + c4.norm());
        n_ = 4;
    }
    else
    {
        // x00 = x[0], x10 = x[1], x11 = x[2]
        const Eigen::Vector3d c1(nagataEdgeCoefficient(x[0], x[1], n[0], n[1]));
        const Eigen::Vector3d c2(nagataEdgeCoefficient(x[1], x[2], n[1], n[2]));
        const Eigen::Vector3d c3(nagataEdgeCoefficient(x[0], x[2], n[0], n[2]));
        c_[0] = x[0];
        c_[1] = x[1] - x[0] - c1;
        c_[2] = x[2] - x[1] + c1 - c3;
        c_[3] = c3 - c1 - c2;
        c_[4] = c1;
        c_[5] = c2;
        bulge_ = 0.25*(c1.norm() + c2.norm() + c3.norm());
        n_ = 3;
    }
}


Eigen::Vector3d NagataPatch::offset(const Eigen::Vector2d& p) const
{
    const double e = p(0);
    const double z = p(1);
    return
        c_[1]*e + c_[2]*z + c_[3]*e*z + c_[4]*e*e + c_[5]*z*z
      + c_[6]*e*e*z + c_[7]*e*z*z;
}


Eigen::Vector3d NagataPatch::point(const Eigen::Vector2d& p) const
{
    return c_[0] + offset(p);
}


Eigen::Matrix<double, 3, 2> NagataPatch::tangents
(
    const Eigen::Vector2d& p
) const
{
    const double e = p(0);
    const double z = p(1);
    Eigen::Matrix<double, 3, 2> J;
    J.col(0) = c_[1] + c_[3]*z + 2*c_[4]*e + 2*c_[6]*e*z + c_[7]*z*z;
    J.col(1) = c_[2] + c_[3]*e + 2*c_[5]*z + c_[6]*e*e + 2*c_[7]*e*z;
    return J;
}


Eigen::Matrix<double, 3, 3> NagataPatch::secondDerivatives
(
    const Eigen::Vector2d& p
) const
{
    const double e = p(0);
    const double z = p(1);
    Eigen::Matrix<double, 3, 3> H;
    H.col(0) = 2*c_[4] + 2*c_[6]*z;
    H.col(1) = c_[3] + 2*c_[6]*e + 2*c_[7]*z;
    H.col(2) = 2*c_[5] + 2*c_[7]*e;
    return H;
}


Eigen::Vector3d NagataPatch::normal(const Eigen::Vector2d& p) const
{
    const Eigen::Matrix<double, 3, 2> J(tangents(p));
    const Eigen::Vector3d n(J.col(0).cross(J.col(1)));
    const double mag = n.norm();
    return mag > 0 ? Eigen::Vector3d(n/mag) : n;
}


Eigen::Vector2d NagataPatch::cornerParam(const int k) const
{
    static const double quad[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    static const double tri[3][2] = {{0, 0}, {1, 0}, {1, 1}};
    const int i = std::max(0, std::min(k, n_ - 1));
    return
        n_ == 4
      ? Eigen::Vector2d(quad[i][0], quad[i][1])
      : Eigen::Vector2d(tri[i][0], tri[i][1]);
}


Eigen::Vector2d NagataPatch::centreParam() const
{
    return n_ == 4 ? Eigen::Vector2d(0.5, 0.5) : Eigen::Vector2d(2.0/3, 1.0/3);
}


bool NagataPatch::clamp(Eigen::Vector2d& p) const
{
    const Eigen::Vector2d p0(p);
    if (n_ == 4)
    {
        p = p.cwiseMax(0.0).cwiseMin(1.0);
        return p == p0;
    }

    // The triangle 0 <= zeta <= eta <= 1: inside, or the closest point of
    // its three edges in the parameter plane
    if (p(1) >= 0 && p(1) <= p(0) && p(0) <= 1)
    {
        return true;
    }
    const auto onSegment = []
    (
        const Eigen::Vector2d& q,
        const Eigen::Vector2d& a,
        const Eigen::Vector2d& b
    )
    {
        const Eigen::Vector2d ab(b - a);
        const double t =
            std::max(0.0, std::min(1.0, (q - a).dot(ab)/ab.squaredNorm()));
        return Eigen::Vector2d(a + t*ab);
    };
    const Eigen::Vector2d a(0, 0), b(1, 0), c(1, 1);
    const Eigen::Vector2d cand[3] =
        {onSegment(p0, a, b), onSegment(p0, b, c), onSegment(p0, a, c)};
    p = cand[0];
    for (int k = 1; k < 3; ++k)
    {
        if ((cand[k] - p0).squaredNorm() < (p - p0).squaredNorm())
        {
            p = cand[k];
        }
    }
    return false;
}


NagataProjection NagataPatch::closest
(
    const Eigen::Vector3d& q,
    const Eigen::Vector2d& start
) const
{
    NagataProjection proj;
    if (!valid())
    {
        return proj;
    }

    // Relative to the first corner: a face far from the origin for its
    // size keeps the distances' digits (else round-off in x hides the
    // last 1e-8 of the face size from the line search)
    const Eigen::Vector3d qr(q - c_[0]);

    // d^2 f/dp^2 of f = |x - q|^2/2 along the directions a and b
    const auto hessian = [&](const Eigen::Vector2d& p, const Eigen::Vector3d& r)
    {
        const Eigen::Matrix<double, 3, 2> J(tangents(p));
        const Eigen::Matrix<double, 3, 3> S(secondDerivatives(p));
        Eigen::Matrix2d H(J.transpose()*J);
        H(0, 0) += r.dot(S.col(0));
        H(0, 1) += r.dot(S.col(1));
        H(1, 0) += r.dot(S.col(1));
        H(1, 1) += r.dot(S.col(2));
        return H;
    };

    // Interior: Newton on both parameters, unconstrained, each step at
    // most a quarter of the domain and halved until f does not grow
    Eigen::Vector2d p(start);
    clamp(p);
    double f = (offset(p) - qr).squaredNorm();
    bool converged = false;
    for (int iter = 0; iter < 50 && !converged; ++iter)
    {
        const Eigen::Vector3d r(offset(p) - qr);
        const Eigen::Matrix<double, 3, 2> J(tangents(p));
        const Eigen::Vector2d g(J.transpose()*r);
        Eigen::Matrix2d H(hessian(p, r));
        const Eigen::Matrix2d GN(J.transpose()*J);
        if (!(H(0, 0) > 0 && H.determinant() > 1e-12*GN.squaredNorm()))
        {
            H = GN;
        }
        if (!(std::abs(H.determinant()) > 0))
        {
            break;
        }
        Eigen::Vector2d step(-H.inverse()*g);
        if (!step.allFinite())
        {
            break;
        }
        if (step.norm() > 0.25)
        {
            step *= 0.25/step.norm();
        }
        double fn = (offset(p + step) - qr).squaredNorm();
        for (int half = 0; half < 40 && fn > f; ++half)
        {
            step *= 0.5;
            fn = (offset(p + step) - qr).squaredNorm();
        }
        if (fn > f)
        {
            converged = true;
            break;
        }
        p += step;
        f = fn;
        converged = step.norm() < 1e-13;
        if (p.cwiseAbs().maxCoeff() > 3)
        {
            // Far outside: the minimum is on an edge
            break;
        }
    }

    Eigen::Vector2d inDomain(p);
    const bool inDomainIterate = clamp(inDomain);
    const bool inside = converged && inDomainIterate;
    if (inside)
    {
        proj.param = p;
        proj.inside = true;
    }
    else
    {
        // The closest point of the boundary: each edge (a + t b, t in
        // [0, 1] in the parameters) by Newton in t from the best of five
        // samples
        const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> edges
        (
            n_ == 4
          ? std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>
            {
                {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0)},
                {Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)},
                {Eigen::Vector2d(0, 1), Eigen::Vector2d(1, 0)},
                {Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 1)}
            }
          : std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>
            {
                {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0)},
                {Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)},
                {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)}
            }
        );
        double best = -1;
        for (const auto& e : edges)
        {
            const Eigen::Vector2d& a = e.first;
            const Eigen::Vector2d& b = e.second;
            const auto fAt = [&](const double t)
            {
                return (offset(a + t*b) - qr).squaredNorm();
            };
            double t = 0;
            double ft = fAt(0);
            for (const double s : {0.25, 0.5, 0.75, 1.0})
            {
                if (fAt(s) < ft)
                {
                    t = s;
                    ft = fAt(s);
                }
            }
            for (int iter = 0; iter < 50; ++iter)
            {
                const Eigen::Vector2d pt(a + t*b);
                const Eigen::Vector3d r(offset(pt) - qr);
                const double g = r.dot(tangents(pt)*b);
                const double h = b.dot(hessian(pt, r)*b);
                const double hGN = (tangents(pt)*b).squaredNorm();
                double dt = -g/(h > 1e-12*hGN ? h : std::max(hGN, 1e-300));
                if (!std::isfinite(dt))
                {
                    break;
                }
                dt = std::max(-0.25, std::min(0.25, dt));
                double tn = std::max(0.0, std::min(1.0, t + dt));
                double fn = fAt(tn);
                for (int half = 0; half < 40 && fn > ft; ++half)
                {
                    dt *= 0.5;
                    tn = std::max(0.0, std::min(1.0, t + dt));
                    fn = fAt(tn);
                }
                if (fn > ft)
                {
                    break;
                }
                const double moved = std::abs(tn - t);
                t = tn;
                ft = fn;
                if (moved < 1e-14)
                {
                    break;
                }
            }
            if (best < 0 || ft < best)
            {
                best = ft;
                proj.param = a + t*b;
            }
        }
        proj.inside = false;

        // An interior iterate Newton left unconverged (a point far from
        // the patch for its size) that is nearer than every edge is kept
        if (inDomainIterate && f < best)
        {
            proj.param = p;
            proj.inside = true;
        }
    }

    proj.point = point(proj.param);
    proj.normal = normal(proj.param);
    proj.distance = (offset(proj.param) - qr).norm();
    return proj;
}


} // End namespace search
} // End namespace c4f

// ************************************************************************* //
