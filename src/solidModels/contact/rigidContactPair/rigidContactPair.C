/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "rigidContactPair.H"
#include "solidPatchTractions.H"
#include "fvMesh.H"

#include <stdexcept>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rigidContactPair::rigidContactPair
(
    const fvPatch& slave,
    const rigidSurface& surface,
    const scalar searchDistance
)
:
    slave_(slave),
    surface_(surface),
    searchDistance_(searchDistance),
    gap_(slave.size(), GREAT),
    normal_(-slave.nf()),
    inRange_(slave.size(), false),
    hitFace_(slave.size(), -1),
    footPoint_(slave.Cf()),
    toolD_(slave.size(), Zero),
    slaveNormals_(slave.nf()),
    overlapFaces_(slave.size()),
    overlapWeights_(slave.size(), scalarList(1, 1.0)),
    overlapGaps_(slave.size(), scalarList(1, GREAT))
{
    forAll(overlapFaces_, i)
    {
        overlapFaces_[i] = labelList(1, i);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::word Foam::rigidContactPair::masterName() const
{
    return "rigid " + surface_.dict().get<word>("type");
}


void Foam::rigidContactPair::update
(
    const vectorField&,
    const vectorField& slaveD
)
{
    const scalar t = slave_.boundaryMesh().mesh().time().value();
    const c4f::rigid::RigidMotion m(surface_.motion(t));
    const vectorField x(slave_.Cf() + slaveD);
    const vectorField nf(slave_.nf());

    forAll(x, i)
    {
        c4f::rigid::SurfacePoint sp;
        try
        {
            sp = surface_.closest(x[i], nf[i], t, searchDistance_);
        }
        catch (const std::exception& e)
        {
            // A non-finite face position (a diverged solve) or motion
            FatalErrorInFunction
                << "Contact patch " << slave_.name() << " at time "
                << slave_.boundaryMesh().mesh().time().timeName()
                << ": the search on the " << masterName() << " failed at"
                << " face " << i << " (centre " << x[i] << "): "
                << e.what() << exit(FatalError);
        }
        const bool found = sp.gap < 0.5*GREAT;
        gap_[i] = sp.gap;
        inRange_[i] = found && sp.gap <= searchDistance_;
        hitFace_[i] = inRange_[i] ? i : -1;
        if (found)
        {
            normal_[i] = c4fConvert::toFoam(sp.normal);
            footPoint_[i] = c4fConvert::toFoam(sp.point);
            toolD_[i] =
                c4fConvert::toFoam(sp.point - m.applyInverse(sp.point));
        }
        else
        {
            normal_[i] = -nf[i];
            footPoint_[i] = x[i];
            toolD_[i] = Zero;
        }
        slaveNormals_[i] = -normal_[i];
        overlapGaps_[i][0] = gap_[i];
    }
}


Foam::labelList Foam::rigidContactPair::passedThrough(scalarField& depth) const
{
    depth.clear();
    return labelList();
}


Foam::tmp<Foam::vectorField> Foam::rigidContactPair::relativeDisplacement
(
    const vectorField& slaveD,
    List<List<vector>>& corrections
) const
{
    corrections.setSize(slave_.size());
    forAll(corrections, i)
    {
        corrections[i] = List<vector>(1, Zero);
    }
    return slaveD - toolD_;
}


Foam::tmp<Foam::scalarField> Foam::rigidContactPair::masterStiffness() const
{
    return tmp<scalarField>(new scalarField(slave_.size(), GREAT));
}


Foam::tmp<Foam::tensorField> Foam::rigidContactPair::masterCellStress() const
{
    return solidPatchTractions::cellFluxStress(slave_);
}


void Foam::rigidContactPair::gatherMasterData
(
    scalarField& K,
    scalarField& delta,
    vectorField& C,
    vectorField& faceCorrection,
    scalarField& magSf
) const
{
    K = scalarField(slave_.size(), 1);
    delta = scalarField(slave_.size(), 0);
    C = vectorField(slave_.size(), Zero);
    faceCorrection = vectorField(slave_.size(), Zero);
    magSf = slave_.magSf();
}


Foam::tmp<Foam::vectorField> Foam::rigidContactPair::masterCellValues
(
    const vectorField&,
    const int
) const
{
    return tmp<vectorField>(new vectorField(toolD_));
}


Foam::tmp<Foam::scalarField> Foam::rigidContactPair::masterCellValues
(
    const UList<solveScalar>&,
    const labelUList&,
    const int
) const
{
    return tmp<scalarField>(new scalarField(slave_.size(), 0));
}


// ************************************************************************* //
