/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "outerCorrectorRelaxation.H"
#include "segregatedRelaxation.H"
#include "uniformVolField.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::outerCorrectorRelaxation::measureQ
(
    const volVectorField& D,
    const solidMaterialLaw& law,
    const volScalarField& impK,
    const bool nonlinearGeometry
)
{
    const fvMesh& mesh = D.mesh();
    const Vector<label>& solved = mesh.solutionD();

    // Small enough for a hyperelastic law's tangent at F = I, far above
    // round-off against the unit stretch
    const scalar strain = 1e-6;

    // rowSum[i]: sigma_ii summed over unit strains along every solved j
    scalarField rowSum[3];
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        rowSum[i].setSize(mesh.nCells(), 0);
    }

    for (direction j = 0; j < vector::nComponents; ++j)
    {
        if (solved[j] < 0)
        {
            continue;
        }
        tensor G(Zero);
        G(j, j) = strain;

        const tmp<volTensorField> probe
        (
            uniformVolField
            (
                mesh, "gradDProbe", dimensionedTensor("gradDProbe", dimless, G)
            )
        );

        // The normal stresses of the probe, whichever stress the solver
        // balances (P's diagonal equals its transpose's)
        scalarField normal[3];
        if (nonlinearGeometry)
        {
            const tmp<volTensorField> tP(law.firstPiola(probe()));
            const tensorField& P = tP().primitiveField();
            normal[0] = P.component(tensor::XX);
            normal[1] = P.component(tensor::YY);
            normal[2] = P.component(tensor::ZZ);
        }
        else
        {
            const tmp<volSymmTensorField> tsigma(law.sigma(probe()));
            const symmTensorField& sigma = tsigma().primitiveField();
            normal[0] = sigma.component(symmTensor::XX);
            normal[1] = sigma.component(symmTensor::YY);
            normal[2] = sigma.component(symmTensor::ZZ);
        }

        for (direction i = 0; i < vector::nComponents; ++i)
        {
            if (solved[i] >= 0)
            {
                rowSum[i] += normal[i]/strain;
            }
        }
    }

    scalar q = 0;
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        if (solved[i] < 0)
        {
            continue;
        }
        forAll(impK, celli)
        {
            q = max
            (
                q,
                c4f::elasticity::volumetricStiffnessRatio
                (
                    rowSum[i][celli],
                    impK[celli]
                )
            );
        }
    }
    return returnReduce(q, maxOp<scalar>());
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::outerCorrectorRelaxation::outerCorrectorRelaxation
(
    const volVectorField& D,
    const solidMaterialLaw& law,
    const volScalarField& impK,
    const bool nonlinearGeometry
)
:
    userFactor_(D.mesh().relaxField(D.name())),
    q_(measureQ(D, law, impK, nonlinearGeometry)),
    omega_(c4f::elasticity::volumetricModeRelaxation(q_))
{
    if (userFactor_)
    {
        Info<< "Outer correctors relaxed by relaxationFactors for "
            << D.name() << ": " << D.mesh().fieldRelaxationFactor(D.name())
            << " (from the bodies' laws it would be " << omega_ << ")"
            << endl;
    }
    else if (omega_ < 1)
    {
        Info<< "Outer correctors relaxed by " << omega_
            << ": the volumetric mode of a body loaded by tractions would"
            << " change by a factor 1 - q = "
            << c4f::elasticity::volumetricModeFactor(q_, 1)
            << " a corrector without it (q = " << q_
            << ", the bodies' largest row sum of normal stiffnesses over K;"
            << " docs/solver.md)" << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::outerCorrectorRelaxation::relax(volVectorField& D) const
{
    if (userFactor_)
    {
        D.relax();
    }
    else if (omega_ < 1)
    {
        D.relax(omega_);
    }
}


// ************************************************************************* //
