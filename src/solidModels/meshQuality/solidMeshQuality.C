/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "solidMeshQuality.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "unitConversion.H"

namespace
{

// The angle between two vectors [deg], 0 for a degenerate one
Foam::scalar angle(const Foam::vector& a, const Foam::vector& b)
{
    using namespace Foam;
    const scalar ab = mag(a)*mag(b);
    if (ab < VSMALL)
    {
        return 0;
    }
    const scalar c = min(max((a & b)/ab, scalar(-1)), scalar(1));
    return radToDeg(Foam::acos(c));
}

} // End anonymous namespace


Foam::solidMeshQuality::solidMeshQuality(const fvMesh& mesh)
:
    maxInternal_(0),
    meanInternal_(0),
    maxPatch_(mesh.boundary().size(), scalar(0)),
    mesh_(mesh)
{
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    const vectorField& C = mesh.C().primitiveField();
    const vectorField& Sf = mesh.Sf().primitiveField();

    scalar sum = 0;
    forAll(nei, facei)
    {
        const scalar a = angle(Sf[facei], C[nei[facei]] - C[own[facei]]);
        maxInternal_ = max(maxInternal_, a);
        sum += a;
    }
    label n = nei.size();
    reduce(maxInternal_, maxOp<scalar>());
    reduce(sum, sumOp<scalar>());
    reduce(n, sumOp<label>());
    meanInternal_ = n ? sum/n : 0;

    // The patches every processor has, in the same order (processor
    // patches come after them and differ in number from processor to
    // processor: a reduce per patch over all of them mismatched, MPI_ERR_
    // TRUNCATE with 3 processors of hertzCylinder)
    const label nGlobal = mesh.boundaryMesh().nNonProcessor();
    for (label patchi = 0; patchi < nGlobal; ++patchi)
    {
        const fvPatch& p = mesh.boundary()[patchi];
        if (!p.coupled())
        {
            const vectorField d(p.Cf() - p.Cn());
            const vectorField& S = p.Sf();
            forAll(d, facei)
            {
                maxPatch_[patchi] = max(maxPatch_[patchi], angle(S[facei], d[facei]));
            }
        }
        reduce(maxPatch_[patchi], maxOp<scalar>());
    }
}


void Foam::solidMeshQuality::report
(
    const word& fieldName,
    const word& contactPatchType
) const
{
    Info<< "Mesh non-orthogonality: internal faces max "
        << maxInternal_ << " deg, mean " << meanInternal_ << " deg" << endl;

    const volVectorField* D =
        mesh_.findObject<volVectorField>(fieldName);

    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        if (!D || D->boundaryField()[patchi].type() != contactPatchType)
        {
            continue;
        }
        Info<< "    contact patch " << p.name() << ": max "
            << maxPatch_[patchi] << " deg (gap at the face centres: corrected)" << endl;
        if (maxPatch_[patchi] > maxContactNonOrthogonality)
        {
            WarningInFunction
                << "Contact patch " << p.name() << " has cells leaning "
                << maxPatch_[patchi] << " deg against their faces (more than "
                << maxContactNonOrthogonality << "): its face values rest"
                << " mostly on the deferred non-orthogonal correction; expect"
                << " more correctors, and refine or smooth the mesh at the"
                << " contact if the pressure is noisy" << endl;
        }
    }

    const word gradName("grad(" + fieldName + ")");
    ITstream& is = mesh_.gradScheme(gradName);
    const word scheme(is.size() ? is[0].wordToken() : word::null);
    const bool gauss =
        scheme == "Gauss"
     || (
            is.size() > 1 && is[1].isWord() && is[1].wordToken() == "Gauss"
        );
    if (gauss && maxInternal_ > maxGaussNonOrthogonality)
    {
        WarningInFunction
            << "gradSchemes " << gradName << " is '" << is
            << "' (system/fvSchemes) on a mesh with non-orthogonal faces"
            << " (max " << maxInternal_ << " deg, more than "
            << maxGaussNonOrthogonality << "): a Gauss gradient there"
            << " stalls the outer correctors of the solid solve (measured on"
            << " tetrahedra: no convergence in 2000 correctors). Use"
            << " 'leastSquares' (or 'pointCellsLeastSquares')" << endl;
    }
}
