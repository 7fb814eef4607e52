/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
-------------------------------------------------------------------------------
Application
    solidContactFoam

Group
    grpStressAnalysisSolvers

Description
    Segregated, cell-centred finite-volume solver for quasi-static solid
    mechanics with contact.

    Each load step (one pseudo-time step) runs outer correctors of

        laplacian(K, D) + div(sigma - K grad D) = 0,

    the implicit/explicit split of Jasak & Weller (2000, IJNME 48:267,
    eq. 14-16): the implicit Laplacian with K = 2mu + lambda carries the
    dominant part of the stress, the explicit remainder is lagged one
    corrector. Boundary conditions, among them the contact conditions, are
    updated inside every corrector, so each corrector alternates the
    displacement solve with the traction/contact update.

    The correctors stop when the normalised initial residual of the D
    equation (OpenFOAM's residual, max over solved components) drops below
    `tolerance`, or after `nCorrectors`. Components whose magnitude stays
    below 1e-10 of the largest are left out: their normalised residual is
    round-off noise.

    Each step prints one summary line:
        Time = <t>  correctors = <n>  residual = <r>  [contact state]

Usage
    In system/fvSolution:
    \table
        Property      | Description                            | Required | Default
        nCorrectors   | max outer correctors per load step     | yes      |
        tolerance     | residual to stop at (> 0)              | yes      |
        verbose       | print every corrector's residual       | no       | no
    \endtable

    \verbatim
    solidMechanics
    {
        nCorrectors     2000;
        tolerance       1e-8;
    }
    \endverbatim

    Fields written: D, sigma, sigmaEq (von Mises), pointD (D interpolated to
    the points, for ParaView's warp-by-vector and foamToVTK).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "pointFields.H"
#include "volPointInterpolation.H"
#include "mechanicalModel.H"
#include "contactStateReporter.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Segregated finite-volume solver for quasi-static solid mechanics"
        " with contact"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "readSolidMechanicsControls.H"
    #include "createFields.H"

    Info<< "\nStarting load stepping\n" << endl;

    while (runTime.loop())
    {
        label nCorr = 0;
        scalar residual = GREAT;

        do
        {
            D.storePrevIter();

            fvVectorMatrix DEqn
            (
                fvm::laplacian(impKf, D, "laplacian(DD,D)")
              + fvc::div(mesh.Sf() & fvc::interpolate(sigma - impK*gradD))
            );

            DEqn.relax();

            const SolverPerformance<vector> perf = DEqn.solve();

            // A component that stays at round-off against the displacement
            // (D_x of a uniaxial nu = 0 column) has a normalised residual
            // of pure noise: it is left out of the convergence measure
            const vector Dmax(gMax(cmptMag(D.primitiveField())));
            const scalar Dscale = cmptMax(Dmax);
            residual = 0;
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                if (Dmax[d] > 1e-10*Dscale)
                {
                    residual = max(residual, perf.initialResidual()[d]);
                }
            }

            D.relax();

            gradD = fvc::grad(D);
            sigma = mech.law().sigma(gradD);

            ++nCorr;

            if (verbose)
            {
                Info<< "    corrector " << nCorr
                    << "  residual = " << residual << endl;
            }
        }
        while (residual > tolerance && nCorr < nCorrectors);

        sigmaEq = sqrt((3.0/2.0)*magSqr(dev(sigma)));
        volPointInterpolation::New(mesh).interpolate(D, pointD);

        Info<< "Time = " << runTime.timeName()
            << "  correctors = " << nCorr
            << "  residual = " << residual
            << contactStateReporter::summary(D).c_str()
            << endl;

        if (residual > tolerance)
        {
            WarningInFunction
                << "Load step at time " << runTime.timeName()
                << " did not converge in nCorrectors = " << nCorrectors
                << " (residual " << residual << " > tolerance "
                << tolerance << ")" << endl;
        }

        runTime.write();
    }

    Info<< nl << "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
        << "  ClockTime = " << runTime.elapsedClockTime() << " s"
        << nl << "End" << nl << endl;

    return 0;
}
