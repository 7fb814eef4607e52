/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "gapLinearization.H"

#include <cmath>

namespace c4f
{
namespace contact
{

namespace
{

typedef Eigen::Matrix<double, 3, 12> Jacobian;

//- [v]x: the matrix of v x (.)
Eigen::Matrix3d cross(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d m;
    m <<     0, -v(2),  v(1),
          v(2),     0, -v(0),
         -v(1),  v(0),     0;
    return m;
}

//- The Jacobian of a point among X = (x2, a, b, c) minus another's: the
//  blocks of +I at `plus` and -I at `minus`
Jacobian difference(const int plus, const int minus)
{
    Jacobian J(Jacobian::Zero());
    J.block<3, 3>(0, 3*plus) = Eigen::Matrix3d::Identity();
    J.block<3, 3>(0, 3*minus) = -Eigen::Matrix3d::Identity();
    return J;
}

GapLinearization invalid()
{
    GapLinearization L;
    L.valid = false;
    L.gap = 0;
    L.normal.setZero();
    L.xi.setZero();
    L.gradient.setZero();
    L.hessian.setZero();
    L.xiGradient.setZero();
    return L;
}

} // End anonymous namespace


GapLinearization linearizeTriangleGap
(
    const Eigen::Vector3d& x2,
    const Eigen::Vector3d& a,
    const Eigen::Vector3d& b,
    const Eigen::Vector3d& c
)
{
    if (!(x2.allFinite() && a.allFinite() && b.allFinite() && c.allFinite()))
    {
        return invalid();
    }

    const Eigen::Vector3d e1(b - a);
    const Eigen::Vector3d e2(c - a);
    const Eigen::Vector3d N(e1.cross(e2));
    const double A = N.norm();
    if (!(A > 1e-14*e1.norm()*e2.norm()))
    {
        return invalid();
    }

    GapLinearization L;
    L.valid = true;
    const Eigen::Vector3d n(N/A);
    const Eigen::Vector3d r(x2 - a);
    const double g = r.dot(n);
    const Eigen::Vector3d rt(r - g*n);
    const Eigen::Vector3d t(rt/A);
    L.gap = g;
    L.normal = n;

    // The gradient: the normal's variation is tangential and r.dn picks
    // up only the tangential part of r, t
    const Eigen::Vector3d gb(e2.cross(t));
    const Eigen::Vector3d gc(t.cross(e1));
    L.gradient.segment<3>(0) = n;
    L.gradient.segment<3>(3) = -(n + gb + gc);
    L.gradient.segment<3>(6) = gb;
    L.gradient.segment<3>(9) = gc;

    // Jacobians of the pieces in X = (x2, a, b, c) (blocks 0..3)
    const Jacobian Jr(difference(0, 1));
    const Jacobian Je1(difference(2, 1));
    const Jacobian Je2(difference(3, 1));
    // dN = de1 x e2 + e1 x de2 = -[e2]x de1 + [e1]x de2
    const Jacobian JN(-cross(e2)*Je1 + cross(e1)*Je2);
    const Eigen::Matrix<double, 1, 12> JA(n.transpose()*JN);
    const Eigen::Matrix3d P(Eigen::Matrix3d::Identity() - n*n.transpose());
    const Jacobian Jn(P*JN/A);
    const Eigen::Matrix<double, 1, 12> Jg(L.gradient.transpose());
    const Jacobian Jt((Jr - n*Jg - g*Jn)/A - rt*JA/(A*A));
    // d(e2 x t) = de2 x t + e2 x dt; d(t x e1) = dt x e1 + t x de1
    const Jacobian Jgb(-cross(t)*Je2 + cross(e2)*Jt);
    const Jacobian Jgc(-cross(e1)*Jt + cross(t)*Je1);

    L.hessian.block<3, 12>(0, 0) = Jn;
    L.hessian.block<3, 12>(3, 0) = -(Jn + Jgb + Jgc);
    L.hessian.block<3, 12>(6, 0) = Jgb;
    L.hessian.block<3, 12>(9, 0) = Jgc;

    // The projection's coordinates by the dual basis of (e1, e2) in the
    // plane, d_a.e_b = delta_ab: xi_a = d_a.r. Not by inverting the metric
    // m_ab = e_a.e_b, whose determinant loses every digit to cancellation
    // once the triangle's angle is below about 1e-8 (a sliver of aspect
    // 1e-8 gave xi = (0.25, 0) for (0.25, 0.1), thinner ones NaN)
    const Eigen::Vector3d d1(e2.cross(n)/A);
    const Eigen::Vector3d d2(n.cross(e1)/A);
    L.xi = Eigen::Vector2d(d1.dot(r), d2.dot(r));
    // d xi_a = m^ab [e_b.(dr - xi1 de1 - xi2 de2) + g n.de_b], m^ab =
    // d_a.d_b and m^ab e_b = d_a
    const Jacobian Jproj(Jr - L.xi(0)*Je1 - L.xi(1)*Je2);
    const Eigen::Matrix<double, 1, 12> nJe1(n.transpose()*Je1);
    const Eigen::Matrix<double, 1, 12> nJe2(n.transpose()*Je2);
    const double m11 = d1.dot(d1), m12 = d1.dot(d2), m22 = d2.dot(d2);
    L.xiGradient.row(0) = d1.transpose()*Jproj + g*(m11*nJe1 + m12*nJe2);
    L.xiGradient.row(1) = d2.transpose()*Jproj + g*(m12*nJe1 + m22*nJe2);

    return L;
}

} // End namespace contact
} // End namespace c4f

// ************************************************************************* //
