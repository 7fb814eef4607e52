/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "triSurfaceRigidSurface.H"
#include "addToRunTimeSelectionTable.H"
#include "triSurface.H"
#include "Time.H"
#include "boundBox.H"

namespace Foam
{
namespace rigidSurfaces
{
    defineTypeNameAndDebug(triSurface, 0);
    addToRunTimeSelectionTable(rigidSurface, triSurface, dictionary);
}
}


Foam::rigidSurfaces::triSurface::triSurface
(
    const dictionary& dict,
    const objectRegistry& db
)
:
    rigidSurface(dict),
    points_(),
    faces_(),
    normals_(),
    size_(0),
    search_()
{
    const fileName file(dict.get<fileName>("file"));
    // The case's own constant/triSurface, also in a decomposed run
    // (processorN/constant has no triSurface: decomposePar does not copy it)
    const fileName full
    (
        db.time().globalPath()/db.time().constant()/"triSurface"/file
    );
    if (!isFile(full))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'file' of " << dict.name() << " is " << file
            << ": no such file " << full << nl
            << "A triSurface tool reads its surface (STL, OBJ, ...) from"
            << " constant/triSurface" << exit(FatalIOError);
    }
    const Foam::triSurface surf(full);
    if (surf.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'file' of " << dict.name() << ": " << full
            << " has no triangles" << exit(FatalIOError);
    }
    const scalar scale = dict.getOrDefault<scalar>("scale", 1);
    if (!(scale > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'scale' of " << dict.name() << " is " << scale
            << "; it must be positive" << exit(FatalIOError);
    }
    points_ = scale*surf.points();
    faces_.setSize(surf.size());
    std::vector<Eigen::Vector3d> pts(points_.size());
    forAll(points_, i)
    {
        pts[i] = c4fConvert::toEigen(points_[i]);
    }
    std::vector<std::vector<int>> tris(surf.size());
    normals_.resize(surf.size());
    forAll(surf, i)
    {
        const labelledTri& t = surf[i];
        faces_[i] = face(t);
        tris[i] = {int(t[0]), int(t[1]), int(t[2])};
        const Eigen::Vector3d nt =
            (pts[t[1]] - pts[t[0]]).cross(pts[t[2]] - pts[t[0]]);
        const double m = nt.norm();
        normals_[i] = m > 0 ? Eigen::Vector3d(nt/m) : Eigen::Vector3d::Zero();
    }
    size_ = boundBox(points_).mag();
    search_.build(pts, tris);

    Info<< "Rigid surface " << file << ": " << surf.size()
        << " triangles, bounding box " << boundBox(points_) << endl;
}


c4f::rigid::SurfacePoint Foam::rigidSurfaces::triSurface::closestReference
(
    const Eigen::Vector3d& X,
    const Eigen::Vector3d& slaveNormal,
    const scalar maxDistance
) const
{
    c4f::rigid::SurfacePoint sp;
    const c4f::search::SearchHit hit = search_.closest(X, maxDistance);
    if (!hit.found)
    {
        sp.point = X;
        sp.normal = Eigen::Vector3d::Zero();
        sp.gap = GREAT;
        sp.valid = false;
        return sp;
    }
    const Eigen::Vector3d& nT = normals_[hit.face];
    const Eigen::Vector3d d = X - hit.point;
    const double dist = d.norm();
    const double s = d.dot(nT) < 0 ? -1 : 1;
    sp.point = hit.point;
    sp.gap = s*dist;
    sp.normal = dist > 1e-9*size_ ? Eigen::Vector3d(s*d/dist) : nT;
    sp.valid = true;

    // Inside the tool, closest to a face that does not face the body (the
    // side of a flat punch, for a point that crossed the bottom near the
    // edge by more than its distance to the side): the face it crossed
    // lies back along the body's normal. Without this a step that pushes
    // a flat punch deeper than the faces next to its edge are from its
    // side pushed those faces sideways onto the side (Sneddon's punch
    // carried 15 % too much normal force, 34 % on the mesh twice finer)
    if (sp.gap < 0 && nT.dot(slaveNormal) > -facingCos_)
    {
        const c4f::search::SearchHit ray =
            search_.firstHit(X, -slaveNormal, maxDistance);
        if (ray.found && normals_[ray.face].dot(slaveNormal) <= -facingCos_)
        {
            const Eigen::Vector3d& nR = normals_[ray.face];
            sp.point = ray.point;
            sp.normal = nR;
            sp.gap = (X - ray.point).dot(nR);
        }
    }
    return sp;
}


void Foam::rigidSurfaces::triSurface::tessellate
(
    const point&,
    const scalar,
    pointField& points,
    faceList& faces
) const
{
    points = points_;
    faces = faces_;
}


// ************************************************************************* //
