/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "normalGap.H"

#include <cmath>

namespace c4f
{
namespace contact
{

TriangleProjection projectOntoTriangle
(
    const Eigen::Vector3d& x2,
    const Eigen::Vector3d& a,
    const Eigen::Vector3d& b,
    const Eigen::Vector3d& c,
    const double tol
)
{
    const Eigen::Vector3d e1 = b - a;
    const Eigen::Vector3d e2 = c - a;
    const Eigen::Vector3d nRaw = e1.cross(e2);

    TriangleProjection p;
    p.normal = nRaw.normalized();
    p.gap = (x2 - a).dot(p.normal);
    p.point = x2 - p.gap*p.normal;

    // Barycentric coordinates from the 2x2 metric of the edges; solving
    // the normal equations keeps them exact for any triangle shape
    const Eigen::Vector3d r = p.point - a;
    const double g11 = e1.dot(e1), g12 = e1.dot(e2), g22 = e2.dot(e2);
    const double det = g11*g22 - g12*g12;
    const double r1 = r.dot(e1), r2 = r.dot(e2);
    const double xi = (g22*r1 - g12*r2)/det;
    const double eta = (g11*r2 - g12*r1)/det;
    p.shape = Eigen::Vector3d(1.0 - xi - eta, xi, eta);
    p.inside = p.shape.minCoeff() >= -tol;
    return p;
}


double normalGap
(
    const Eigen::Vector3d& x2,
    const Eigen::Vector3d& x1bar,
    const Eigen::Vector3d& n1bar
)
{
    return (x2 - x1bar).dot(n1bar);
}


double planeGap
(
    const Eigen::Vector3d& c,
    const Eigen::Vector3d& xm,
    const Eigen::Vector3d& nm,
    const Eigen::Vector3d& xs,
    const Eigen::Vector3d& ns
)
{
    const double nn = ns.dot(nm);
    if (!(std::abs(nn) >= 1e-6*ns.norm()))
    {
        return nm.dot(xs - xm);
    }
    return nm.dot(c - xm) + ns.dot(xs - c)/nn;
}


Eigen::Matrix<double, 3, 4> gapGradient(const TriangleProjection& p)
{
    Eigen::Matrix<double, 3, 4> G;
    G.col(0) = p.normal;
    G.col(1) = -p.shape(0)*p.normal;
    G.col(2) = -p.shape(1)*p.normal;
    G.col(3) = -p.shape(2)*p.normal;
    return G;
}

} // End namespace contact
} // End namespace c4f
