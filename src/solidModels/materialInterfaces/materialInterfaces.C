/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "materialInterfaces.H"
#include "bimaterialInterface.H"
#include "eigenFoamConversions.H"
#include "fvc.H"
#include "harmonic.H"
#include "linear.H"
#include "gaussGrad.H"
#include "uniformVolField.H"

namespace Foam
{
    defineTypeNameAndDebug(materialInterfaces, 0);
}


namespace
{

//- The two sides of a face of weight w (P's linear weight, d_N/d) and
//  normal distance d = 1/nonOrthDeltaCoeff between the cell centres
void faceSides
(
    const Foam::scalar KP,
    const Foam::scalar KN,
    const Foam::scalar w,
    const Foam::scalar deltaCoeff,
    c4f::elasticity::InterfaceSide& P,
    c4f::elasticity::InterfaceSide& N
)
{
    const Foam::scalar d = 1.0/deltaCoeff;
    P = {KP, (1 - w)*d};
    N = {KN, w*d};
}

} // End anonymous namespace


Foam::materialInterfaces::materialInterfaces
(
    const fvMesh& mesh,
    const labelUList& cellMaterial
)
:
    mesh_(mesh),
    faces_(),
    patchFaces_(mesh.boundary().size()),
    cells_(),
    nGlobal_(0)
{
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();

    DynamicList<label> faces;
    forAll(nei, facei)
    {
        if (cellMaterial[own[facei]] != cellMaterial[nei[facei]])
        {
            faces.append(facei);
        }
    }
    faces_.transfer(faces);

    // The neighbour's material across a coupled patch comes with the swap
    tmp<volScalarField> tmaterial
    (
        uniformVolField(mesh, "cellMaterial", dimensionedScalar(dimless, Zero))
    );
    volScalarField& material = tmaterial.ref();
    forAll(cellMaterial, celli)
    {
        material[celli] = cellMaterial[celli];
    }
    material.correctBoundaryConditions();

    boolList isInterfaceCell(mesh.nCells(), false);
    for (const label facei : faces_)
    {
        isInterfaceCell[own[facei]] = true;
        isInterfaceCell[nei[facei]] = true;
    }

    label n = faces_.size();
    forAll(mesh.boundary(), patchi)
    {
        const fvPatchScalarField& pf = material.boundaryField()[patchi];
        if (!pf.coupled())
        {
            continue;
        }
        const scalarField mP(pf.patchInternalField());
        const scalarField mN(pf.patchNeighbourField());
        const labelUList& faceCells = mesh.boundary()[patchi].faceCells();

        DynamicList<label> pFaces;
        forAll(mP, facei)
        {
            if (mag(mP[facei] - mN[facei]) > 0.5)
            {
                pFaces.append(facei);
                isInterfaceCell[faceCells[facei]] = true;
            }
        }
        patchFaces_[patchi].transfer(pFaces);
        n += patchFaces_[patchi].size();
    }

    DynamicList<label> cells;
    forAll(isInterfaceCell, celli)
    {
        if (isInterfaceCell[celli])
        {
            cells.append(celli);
        }
    }
    cells_.transfer(cells);

    nGlobal_ = returnReduce(n, sumOp<label>());

    if (nGlobal_ > 0)
    {
        Info<< "Bonded material interfaces: " << nGlobal_ << " faces, "
            << returnReduce(cells_.size(), sumOp<label>())
            << " cells next to them" << endl;
    }
}


Foam::tmp<Foam::surfaceScalarField>
Foam::materialInterfaces::interpolateK(const volScalarField& K) const
{
    return harmonic(mesh_).interpolate(K);
}


Foam::tmp<Foam::surfaceTensorField>
Foam::materialInterfaces::interpolateExplicit
(
    const volTensorField& R,
    const volScalarField& K
) const
{
    tmp<surfaceTensorField> tRf(fvc::interpolate(R));
    if (!active())
    {
        return tRf;
    }
    surfaceTensorField& Rf = tRf.ref();

    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const surfaceScalarField& w = mesh_.weights();
    const surfaceScalarField& dc = mesh_.nonOrthDeltaCoeffs();

    c4f::elasticity::InterfaceSide P, N;

    for (const label facei : faces_)
    {
        const label p = own[facei], q = nei[facei];
        faceSides(K[p], K[q], w[facei], dc[facei], P, N);
        const scalar wP = c4f::elasticity::explicitTractionWeight(P, N);
        Rf[facei] = wP*R[p] + (1 - wP)*R[q];
    }

    forAll(patchFaces_, patchi)
    {
        if (patchFaces_[patchi].empty())
        {
            continue;
        }
        const fvPatchTensorField& Rp = R.boundaryField()[patchi];
        const tensorField RP(Rp.patchInternalField());
        const tensorField RN(Rp.patchNeighbourField());
        const fvPatchScalarField& Kp = K.boundaryField()[patchi];
        const scalarField KP(Kp.patchInternalField());
        const scalarField KN(Kp.patchNeighbourField());
        const scalarField& wp = w.boundaryField()[patchi];
        const scalarField& dcp = dc.boundaryField()[patchi];
        fvsPatchTensorField& Rfp = Rf.boundaryFieldRef()[patchi];

        for (const label facei : patchFaces_[patchi])
        {
            faceSides(KP[facei], KN[facei], wp[facei], dcp[facei], P, N);
            const scalar wP = c4f::elasticity::explicitTractionWeight(P, N);
            Rfp[facei] = wP*RP[facei] + (1 - wP)*RN[facei];
        }
    }

    return tRf;
}


Foam::tmp<Foam::surfaceVectorField>
Foam::materialInterfaces::faceDisplacement
(
    const volVectorField& D,
    const volTensorField& R,
    const volScalarField& K
) const
{
    using c4fConvert::toEigen;
    using c4fConvert::toFoam;

    tmp<surfaceVectorField> tDf(linearInterpolate(D));
    surfaceVectorField& Df = tDf.ref();

    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const surfaceScalarField& w = mesh_.weights();
    const surfaceScalarField& dc = mesh_.nonOrthDeltaCoeffs();
    const surfaceVectorField& Sf = mesh_.Sf();
    const surfaceScalarField& magSf = mesh_.magSf();

    c4f::elasticity::InterfaceSide P, N;

    for (const label facei : faces_)
    {
        const label p = own[facei], q = nei[facei];
        const vector n(Sf[facei]/magSf[facei]);
        faceSides(K[p], K[q], w[facei], dc[facei], P, N);
        Df[facei] = toFoam
        (
            c4f::elasticity::interfaceDisplacement
            (
                P, toEigen(D[p]), toEigen(n & R[p]),
                N, toEigen(D[q]), toEigen(n & R[q])
            )
        );
    }

    forAll(patchFaces_, patchi)
    {
        if (patchFaces_[patchi].empty())
        {
            continue;
        }
        const fvPatchVectorField& Dp = D.boundaryField()[patchi];
        const vectorField DP(Dp.patchInternalField());
        const vectorField DN(Dp.patchNeighbourField());
        const fvPatchTensorField& Rp = R.boundaryField()[patchi];
        const tensorField RP(Rp.patchInternalField());
        const tensorField RN(Rp.patchNeighbourField());
        const fvPatchScalarField& Kp = K.boundaryField()[patchi];
        const scalarField KP(Kp.patchInternalField());
        const scalarField KN(Kp.patchNeighbourField());
        const scalarField& wp = w.boundaryField()[patchi];
        const scalarField& dcp = dc.boundaryField()[patchi];
        const vectorField np(mesh_.boundary()[patchi].nf());
        fvsPatchVectorField& Dfp = Df.boundaryFieldRef()[patchi];

        for (const label facei : patchFaces_[patchi])
        {
            const vector& n = np[facei];
            faceSides(KP[facei], KN[facei], wp[facei], dcp[facei], P, N);
            Dfp[facei] = toFoam
            (
                c4f::elasticity::interfaceDisplacement
                (
                    P, toEigen(DP[facei]), toEigen(n & RP[facei]),
                    N, toEigen(DN[facei]), toEigen(n & RN[facei])
                )
            );
        }
    }

    return tDf;
}


Foam::tmp<Foam::volTensorField> Foam::materialInterfaces::grad
(
    const volVectorField& D,
    const volTensorField& R,
    const volScalarField& K
) const
{
    tmp<volTensorField> tgrad(fvc::grad(D));
    if (!active())
    {
        return tgrad;
    }
    volTensorField& g = tgrad.ref();

    const tmp<surfaceVectorField> tDf(faceDisplacement(D, R, K));
    const volTensorField gauss
    (
        fvc::surfaceIntegrate(mesh_.Sf()*tDf())
    );
    for (const label celli : cells_)
    {
        g[celli] = gauss[celli];
    }

    // The boundary values follow the corrected cells, as in the
    // gradient schemes themselves
    g.correctBoundaryConditions();
    fv::gaussGrad<vector>::correctBoundaryConditions(D, g);

    return tgrad;
}
