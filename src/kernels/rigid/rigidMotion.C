/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "rigidMotion.H"

#include <stdexcept>

namespace c4f
{
namespace rigid
{

RigidMotion::RigidMotion()
:
    translation_(Eigen::Vector3d::Zero()),
    centre_(Eigen::Vector3d::Zero()),
    rotation_(Eigen::Matrix3d::Identity())
{}


RigidMotion::RigidMotion
(
    const Eigen::Vector3d& translation,
    const Eigen::Vector3d& rotationVector,
    const Eigen::Vector3d& centre
)
:
    translation_(translation),
    centre_(centre),
    rotation_(Eigen::Matrix3d::Identity())
{
    if
    (
        !translation.allFinite()
     || !rotationVector.allFinite()
     || !centre.allFinite()
    )
    {
        throw std::invalid_argument("rigid motion: non-finite component");
    }

    // Scaled by the largest component so that neither a 1e-170 nor a
    // 1e170 angle under- or overflows in its square. A zero angle has no
    // axis (0/0); the identity is also the exact answer there, so a tool
    // that does not turn moves by u alone.
    const double m = rotationVector.cwiseAbs().maxCoeff();
    const double angle = m > 0 ? m*(rotationVector/m).norm() : 0.0;
    if (angle > 0)
    {
        rotation_ = Eigen::AngleAxisd(angle, rotationVector/angle)
            .toRotationMatrix();
    }
}


Eigen::Vector3d RigidMotion::apply(const Eigen::Vector3d& X) const
{
    return centre_ + translation_ + rotation_*(X - centre_);
}


Eigen::Vector3d RigidMotion::applyInverse(const Eigen::Vector3d& x) const
{
    // Q^T: the inverse of an orthogonal Q, without a solve
    return centre_ + rotation_.transpose()*(x - centre_ - translation_);
}


Eigen::Vector3d RigidMotion::displacement(const Eigen::Vector3d& X) const
{
    // u + (Q - I)(X - c) rather than apply(X) - X: far from the origin the
    // difference of two large positions would lose the small displacement
    const Eigen::Vector3d r = X - centre_;
    return translation_ + (rotation_*r - r);
}


Eigen::Vector3d RigidMotion::rotateVector(const Eigen::Vector3d& v) const
{
    return rotation_*v;
}

} // End namespace rigid
} // End namespace c4f
