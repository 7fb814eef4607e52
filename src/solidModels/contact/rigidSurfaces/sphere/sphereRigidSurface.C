/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "sphereRigidSurface.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace rigidSurfaces
{
    defineTypeNameAndDebug(sphere, 0);
    addToRunTimeSelectionTable(rigidSurface, sphere, dictionary);
}
}


Foam::rigidSurfaces::sphere::sphere
(
    const dictionary& dict,
    const objectRegistry&
)
:
    rigidSurface(dict),
    centre_(dict.get<vector>("centre")),
    radius_(readPositive("radius")),
    inside_(dict.getOrDefault<bool>("inside", false))
{}


c4f::rigid::SurfacePoint Foam::rigidSurfaces::sphere::closestReference
(
    const Eigen::Vector3d& X,
    const Eigen::Vector3d&,
    const scalar
) const
{
    return
        c4f::rigid::closestOnSphere(X, c4fConvert::toEigen(centre_), radius_, inside_);
}


void Foam::rigidSurfaces::sphere::tessellate
(
    const point&,
    const scalar,
    pointField& points,
    faceList& faces
) const
{
    // Latitude-longitude quads, 24 x 48, poles along y
    const label nTheta = 24;
    const label nPhi = 48;
    const scalar pi = constant::mathematical::pi;
    points.setSize((nTheta + 1)*nPhi);
    forAll(points, k)
    {
        const scalar theta = pi*(k/nPhi)/nTheta;
        const scalar phi = 2*pi*(k % nPhi)/nPhi;
        points[k] =
            centre_
          + radius_
           *vector
            (
                sin(theta)*cos(phi), cos(theta), sin(theta)*sin(phi)
            );
    }
    faces.setSize(nTheta*nPhi);
    forAll(faces, k)
    {
        const label i = k/nPhi;
        const label j = k % nPhi;
        const label j1 = (j + 1) % nPhi;
        face f(4);
        f[0] = i*nPhi + j;
        f[1] = i*nPhi + j1;
        f[2] = (i + 1)*nPhi + j1;
        f[3] = (i + 1)*nPhi + j;
        faces[k] = f;
    }
}


// ************************************************************************* //
