/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "hyperelasticLaws.H"

#include <cmath>

namespace c4f
{
namespace elasticity
{

namespace
{

inline int v(const int i, const int J)
{
    return i + 3*J;
}

//- St Venant-Kirchhoff's second Piola-Kirchhoff stress S(E(F))
Eigen::Matrix3d stVenantKirchhoffPK2(const Eigen::Matrix3d& F, const Lame& p)
{
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d E = 0.5*(F.transpose()*F - I);
    return p.lambda*E.trace()*I + 2*p.mu*E;
}

} // namespace


Eigen::Matrix3d deformationGradient(const Eigen::Matrix3d& gradD)
{
    return Eigen::Matrix3d::Identity() + gradD.transpose();
}


JacobianCheck checkJacobian(const Eigen::Matrix3d& F)
{
    if (!F.allFinite())
    {
        return JacobianCheck::notFinite;
    }
    const double J = F.determinant();
    if (!std::isfinite(J))
    {
        return JacobianCheck::notFinite;
    }
    return J > 0 ? JacobianCheck::ok : JacobianCheck::nonPositive;
}


std::string describe(const JacobianCheck c)
{
    switch (c)
    {
        case JacobianCheck::ok:
            return "the deformation gradient is admissible";
        case JacobianCheck::notFinite:
            return "the deformation gradient is not finite";
        case JacobianCheck::nonPositive:
            return "J = det F <= 0: the cell is turned inside out (a valid"
                " deformation has J > 0; a smaller load step or a finer mesh"
                " where the strain is largest may help)";
    }
    return "unknown check";
}


Eigen::Matrix3d stVenantKirchhoffPK1(const Eigen::Matrix3d& F, const Lame& p)
{
    return F*stVenantKirchhoffPK2(F, p);
}


Tangent9 stVenantKirchhoffTangent(const Eigen::Matrix3d& F, const Lame& p)
{
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d S = stVenantKirchhoffPK2(F, p);
    const Eigen::Matrix3d b = F*F.transpose();

    Tangent9 A;
    for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J)
    for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L)
    {
        A(v(i, J), v(k, L)) =
            I(i, k)*S(L, J)
          + p.lambda*F(i, J)*F(k, L)
          + p.mu*F(i, L)*F(k, J)
          + p.mu*b(i, k)*I(J, L);
    }
    return A;
}


Eigen::Matrix3d neoHookeanPK1(const Eigen::Matrix3d& F, const Lame& p)
{
    const Eigen::Matrix3d FinvT = F.inverse().transpose();
    const double lnJ = std::log(F.determinant());
    return p.mu*(F - FinvT) + p.lambda*lnJ*FinvT;
}


Tangent9 neoHookeanTangent(const Eigen::Matrix3d& F, const Lame& p)
{
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d Fi = F.inverse();
    const double lnJ = std::log(F.determinant());

    Tangent9 A;
    for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J)
    for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L)
    {
        A(v(i, J), v(k, L)) =
            p.mu*I(i, k)*I(J, L)
          + p.lambda*Fi(L, k)*Fi(J, i)
          + (p.mu - p.lambda*lnJ)*Fi(L, i)*Fi(J, k);
    }
    return A;
}


Eigen::Matrix3d decoupledNeoHookeanPK1(const Eigen::Matrix3d& F, const Lame& p)
{
    const Eigen::Matrix3d FinvT = F.inverse().transpose();
    const double J = F.determinant();
    const double a = std::pow(J, -2.0/3.0);
    const double I1 = (F.transpose()*F).trace();
    const double K = p.lambda + 2.0*p.mu/3.0;
    return p.mu*a*(F - I1/3.0*FinvT) + K*(J - 1)*J*FinvT;
}


Tangent9 decoupledNeoHookeanTangent(const Eigen::Matrix3d& F, const Lame& p)
{
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d Fi = F.inverse();
    const double J = F.determinant();
    const double a = std::pow(J, -2.0/3.0);
    const double I1 = (F.transpose()*F).trace();
    const double K = p.lambda + 2.0*p.mu/3.0;

    Tangent9 A;
    for (int i = 0; i < 3; ++i)
    for (int Jc = 0; Jc < 3; ++Jc)
    for (int k = 0; k < 3; ++k)
    for (int L = 0; L < 3; ++L)
    {
        A(v(i, Jc), v(k, L)) =
            p.mu*a
           *(
                I(i, k)*I(Jc, L)
              - 2.0/3.0*Fi(L, k)*(F(i, Jc) - I1/3.0*Fi(Jc, i))
              - 2.0/3.0*F(k, L)*Fi(Jc, i)
              + I1/3.0*Fi(Jc, k)*Fi(L, i)
            )
          + K*((2*J - 1)*J*Fi(L, k)*Fi(Jc, i) - (J*J - J)*Fi(Jc, k)*Fi(L, i));
    }
    return A;
}


Eigen::Matrix3d cauchyFromPK1(const Eigen::Matrix3d& P, const Eigen::Matrix3d& F)
{
    return P*F.transpose()/F.determinant();
}


double areaRatio(const Eigen::Matrix3d& F, const Eigen::Vector3d& N, Eigen::Vector3d* n)
{
    const Eigen::Vector3d nda = F.determinant()*F.inverse().transpose()*N;
    const double ratio = nda.norm();
    if (n)
    {
        *n = ratio > 0 ? Eigen::Vector3d(nda/ratio) : Eigen::Vector3d::Zero();
    }
    return ratio;
}

} // End namespace elasticity
} // End namespace c4f

// ************************************************************************* //
