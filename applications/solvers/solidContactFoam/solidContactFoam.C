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

    A load step has converged when, after an outer corrector,
      - the normalised initial residual of the D equation (OpenFOAM's
        residual, max over solved components) is below `tolerance`: the
        boundary conditions, the contact conditions among them, were
        updated before that solve, so the residual holds their face values;
      - no contact patch changed its active set in that corrector;
      - the total normal force of every contact patch with active faces
        changed by less than `tolerance` relative in that corrector (from
        the state the corrector started from to the state its solve gave;
        with none active the force is the residual traction, which the
        residual test covers);
      - every contact method with stored multipliers (augmented Lagrange,
        cross-constraint, perturbed Lagrange) found them converged: when
        the three tests above pass, such a method updates its multipliers
        (Uzawa), and while they move the correctors go on from the
        converged state; a method that reaches its maximum number of
        updates unconverged fails the step.
    A contact method that keeps its gaps open (barrier) limits each
    corrector's update of D, after the solve and after Anderson's step
    (which can penetrate too; the barrier where a face out of its range
    would close, every face in a Newton step): D moves back along the
    update to
    x_k + alpha (x_k+1 - x_k) until the method admits the gaps it measures
    there (contactStateReporter::stepLimit, outerCorrectorAcceleration::
    scaleStep).
    The plain iteration keeps the solve's D at convergence; the
    accelerated one keeps the state the test was made at, which is a fixed
    point of the corrector to the tolerance (the traction and contact
    faces are set consistently with their gradients, see
    outerCorrectorAcceleration).

    By default (`acceleration anderson`) the outer correctors are
    accelerated by Anderson's method (IQN-ILS; Walker & Ni 2011, SIAM J.
    Numer. Anal. 49:1715) over the cell values and the face values of the
    non-coupled patches (outerCorrectorAcceleration): after each corrector
    that has not converged, D becomes the combination of the last
    andersonDepth + 1 iterates whose corrector residual is least. The
    history starts afresh with each load step and whenever a contact
    patch changed its active set (with `andersonActiveSetChange secant`
    the iterate is kept: the next step is the secant through the change).
    With `andersonRestartGrowth g` it also
    starts afresh when an accelerated corrector's residual |G(x) - x| is
    more than g times the one before (the secants described a map that is
    no longer there: a face at a sharp master corner that switched
    between two positions). `acceleration none` is the plain
    iteration. Measured at tolerance 1e-9: plateHole 36 correctors
    instead of 204, hertzCylinder 45 (LM) instead of 222; make bench
    prints the table.

    Components of D whose magnitude stays below `residualFloor` (1e-10)
    of the largest are left out of the residual: their normalised residual
    is round-off noise. The system's condition number can lift round-off
    above 1e-10: the ironing's die pressed straight down with its contact
    patches prescribed held D_x at 1.0e-10 to 1.2e-9 of D_y, whose
    normalised residual stayed at 4e-7 to 0.2 for 5000 correctors while
    Anderson's |G(x) - x| was 1e-20 (residualFloor 1e-8 converges it).
    A larger floor is not the default: a genuine small component can
    carry the answer (contactPatchTest with a 1000 times stiffer upper
    block, nu = 0: with the floor at 1e-8 the stress was 2.7e-6 from
    uniform against 1e-6).

    A step that has not converged in `nCorrectors` stops the run with a
    FatalError naming the time, the residual and the contact state; the
    step is not written, so the last time on disk is the last converged
    one. `onNonConvergence continue` warns and goes on instead (the step is
    then written and contactReport's `converged` column shows 0).

    Finite deformation (`nonlinearGeometry yes`): the total-Lagrangian
    balance on the reference mesh, Div P = 0 with P the first
    Piola-Kirchhoff stress of F = I + grad(D)^T (the material description
    of Bonet & Wood, Nonlinear Continuum Mechanics for Finite Element
    Analysis, 2nd ed., 2008, ch. 6), split the same way:

        laplacian(K, D) + div(P^T - K grad D) = 0.

    D stays the unknown, so contact, restart, decomposition and Anderson
    act on it unchanged. A prescribed traction (solidTraction) is then per
    reference area (P.N). Every step's last iterate must have J = det F > 0
    in every cell: a FatalError names the first cell turned inside out and
    the time, before anything of the step is written (an iterate on the
    way may pass through J <= 0: the laws then give their small-strain
    stress). `sigma` is the Cauchy stress P F^T / J.

    With `algorithm newtonKrylov` each load step is solved by a
    Jacobian-free Newton-Krylov loop on the same corrector instead
    (newtonKrylovCorrector): the corrector's solve then takes a fixed
    number of GAMG cycles, the convergence test is the same, and
    `correctors` counts every corrector, GMRES's products included. A
    load step starts with segregated correctors (`acceleration`, full
    solves: the load increment and the contact decisions it causes) until
    one leaves the contact state unchanged, at most maxSegregatedStart of
    them. A step that has not converged in
    maxNewtonSteps Newton steps goes on with the segregated correctors.

    At the fixed point the split leaves div(sigma) plus the smoothing term
    K [laplacian(D) - div((grad D)_f)] (zero for a linear field; it damps
    the cell-to-cell oscillations the interpolated gradient cannot see).
    Sized by K, it over-smooths a near-incompressible body, where K is
    2 (1 - nu)/(1 - 2 nu) times the shear modulus: `stabilisationScale s`
    keeps s K of it, the rest taken out explicitly (K stays the implicit
    coefficient), at the price of a contraction of only 1 - s per
    corrector for those oscillations. hertzCylinder with nu = 0.49: p0
    10.6 % off Hertz with s = 1, 1.9 % with 0.1 (228 and 1122 correctors;
    docs/solver.md, "Near-incompressible bodies").

    The split is a Jacobi iteration on the normal stresses of a body
    loaded by tractions; in 3D its volumetric mode changes by
    -2 nu/(1 - nu) a corrector, unstable above nu = 1/3 (hertzSphere and
    the 3D patch test diverged at nu = 0.45). Each corrector's update is
    relaxed by omega = (5/3)/q from the laws where q > 2
    (outerCorrectorRelaxation; 1, nothing changed, up to nu = 1/3 in 3D),
    or by the case's relaxationFactors for D.

    Each step prints one summary line:
        Time = <t>  correctors = <n>  residual = <r>  [contact state]

Usage
    In system/fvSolution:
    \table
        Property      | Description                            | Required | Default
        nCorrectors   | max outer correctors per load step     | yes      |
        tolerance     | residual to stop at (> 0)              | yes      |
        verbose       | print every corrector's residual       | no       | no
        residualFloor | components of D below this fraction of the largest leave the residual ([0, 1)) | no | 1e-10
        onNonConvergence | stop or continue                    | no       | stop
        acceleration  | anderson or none                       | no       | anderson
        andersonDepth | difference columns kept (>= 1)         | no       | 15
        andersonRestartGrowth | restart when a step grows the residual by more (>= 1) | no | never
        andersonActiveSetChange | restart, or secant: the step through an active-set change is a one-column secant (outerCorrectorAcceleration) | no | restart
        nonlinearGeometry | finite deformation (total Lagrangian) | no | no
        stabilisationScale | share s of K in the smoothing term ((0, 1]; 0.1 for nu >= 0.45) | no | 1
        algorithm     | segregated or newtonKrylov             | no       | segregated
    \endtable

    `solidContactFoam -listMethods` prints the contact methods of the
    run-time selection table, one per line, each with its traits
    (contactMethodTraits), the one list of method facts the tutorials,
    tests and benchmarks read:

        <name> answer=<exact|penalty|constitutive|barrier> openStart=<yes|no>
            slip=<yes|no> multipliers=<none|augmented|regularised>
            coeffs=<entry:default,...|->

    `-listFrictionModels` prints the friction models, one per line.

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
#include "materialInterfaces.H"
#include "contactStateReporter.H"
#include "contactMethod.H"
#include "frictionModel.H"
#include "contactFvMesh.H"
#include "outerCorrectorAcceleration.H"
#include "outerCorrectorRelaxation.H"
#include "newtonKrylovCorrector.H"
#include "solidMeshQuality.H"
#include "checkAdmissible.H"
#include "zeroGradientFvPatchFields.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Segregated finite-volume solver for quasi-static solid mechanics"
        " with contact"
    );

    argList::addBoolOption
    (
        "listMethods",
        "print the contact methods (the values of a solidContact slave's"
        " `method` entry), one per line with their traits, and exit"
    );

    argList::addBoolOption
    (
        "listFrictionModels",
        "print the friction models (the values of a solidContact slave's"
        " `friction` entry), one per line, and exit"
    );

    // Tutorials, tests and benchmarks take the method list from here: it
    // is the run-time selection table, so a new method is found by all.
    // Printed before argList's banner, so that it is the whole output
    for (int i = 1; i < argc; ++i)
    {
        const std::string opt(argv[i]);
        if (opt == "-listMethods" || opt == "-listFrictionModels")
        {
            if (opt == "-listMethods")
            {
                contactMethod::printTable(std::cout);
                return 0;
            }
            for
            (
                const word& m
              : frictionModel::dictionaryConstructorTablePtr_->sortedToc()
            )
            {
                std::cout << m << '\n';
            }
            return 0;
        }
    }

    argList args(argc, argv);

    if (!args.checkRootCase())
    {
        FatalError.exit();
    }
    #include "createTime.H"
    #include "createContactMesh.H"
    #include "readSolidMechanicsControls.H"
    #include "createFields.H"
    mesh.checkSolverControls(D);

    // The explicit remainder of the stress: (sigma or P^T) - K grad D
    const auto explicitStress = [&]() -> tmp<volTensorField>
    {
        return
            nonlinearGeometry
          ? stressFluxPtr() - impK*gradD
          : sigma - impK*gradD;
    };

    // At the fixed point the D equation is div(sigma) plus the smoothing
    // term s K [laplacian(D) - div((grad D)_f)], the two-point Laplacian
    // of the face against the interpolated cell gradients: zero for a
    // field linear in space, it damps cell-to-cell oscillations that the
    // interpolated gradient does not see (Jasak & Weller 2000, IJNME
    // 48:267, with s = 1). Its size follows K = 2 mu + lambda, not the
    // shear modulus, so a near-incompressible body is smoothed as if it
    // were 2 (1 - nu)/(1 - 2 nu) times stiffer in shear (51 at nu = 0.49,
    // plane strain): hertzCylinder with nu = 0.49 was 10.6 % off Hertz in
    // p0 at s = 1, 1.9 % at 0.1 (docs/solver.md). K stays the implicit
    // coefficient (the corrector's contraction needs it); s < 1 takes
    // (1 - s) K of the smoothing out explicitly, which leaves the
    // oscillation modes a contraction of 1 - s per corrector
    const scalar stabilisationRemoved = 1 - stabilisationScale;

    // The relaxation of each corrector's update: the case's factor for D,
    // else one from the laws that keeps a body loaded by tractions from
    // growing its volumetric mode (3D, nu > 1/3; its header says why)
    const outerCorrectorRelaxation relaxation
    (
        D, mech.law(), impK, nonlinearGeometry
    );

    // Anderson acceleration of the outer correctors, or none
    outerCorrectorAcceleration acceleration(solidControls, D);

    // Or Newton-Krylov on the correctors (algorithm newtonKrylov)
    const bool newton = newtonKrylovCorrector::selected(solidControls);
    newtonKrylovCorrector newtonLoop(solidControls, D);

    // Whether this corrector is Newton's: newtonKrylovCorrector decides
    // (the segregated start until the contact state settles, the
    // segregated correctors after maxNewtonSteps; its header says why)
    bool newtonNow = false;
    label nSegregated = 0;

    // The stress of the current D (grad D, sigma; P under finite
    // deformation), which the next assembly's explicit part takes
    const auto updateStress = [&]()
    {
        gradD = interfaces.grad(D, explicitStress(), impK);
        if (nonlinearGeometry)
        {
            const tmp<volTensorField> P(mech.law().firstPiola(gradD));
            stressFluxPtr() = P().T();
            sigma = finiteStrainFields::cauchy(P(), gradD);
        }
        else
        {
            sigma = mech.law().sigma(gradD);
        }
    };

    // A diverging corrector sequence stops here with what happened, before
    // the laws, the search or the linear solver meet numbers they cannot
    // hold (a neo-Hookean stress of |F| ~ 1e100 overflowed into SIGFPE):
    // no displacement is a thousand times the bodies' extent
    const scalar extent = mesh.bounds().mag();
    const auto checkDiverged = [&](const label nCorr)
    {
        const scalar Dmax = gMax(mag(D.primitiveField())());
        if (!std::isfinite(Dmax) || Dmax > 1e3*extent)
        {
            FatalErrorInFunction
                << "Load step at time " << runTime.timeName()
                << ", corrector " << nCorr << ": the outer correctors"
                << " diverged (max |D| = " << Dmax << " m, the mesh's extent "
                << extent << " m); nothing of this step is written. A"
                << " smaller load step (deltaT) may converge"
                << (
                       stabilisationScale < 1
                     ? "; so may a larger stabilisationScale (now "
                     + Foam::name(stabilisationScale) + ", docs/solver.md)"
                     : string()
                   ).c_str()
                << exit(FatalError);
        }
    };

    // Assemble the D equation (the boundary conditions, the contact ones
    // among them, updated from D) and solve it: the solver's controls, or
    // Newton-Krylov's fixed cycles
    const auto solveD = [&]() -> SolverPerformance<vector>
    {
        fvVectorMatrix DEqn
        (
            fvm::laplacian(impKf, D, "laplacian(DD,D)")
          + fvc::div
            (
                mesh.Sf()
              & interfaces.interpolateExplicit
                (
                    stabilisationRemoved > 0
                  ? explicitStress() + stabilisationRemoved*impK*gradD
                  : explicitStress(),
                    impK
                )
            )
        );
        if (stabilisationRemoved > 0)
        {
            DEqn -=
                stabilisationRemoved
               *fvc::laplacian(impKf, D, "laplacian(DD,D)");
        }

        DEqn.relax();

        const SolverPerformance<vector> perf =
            newtonNow
          ? DEqn.solve
            (
                newtonLoop.solverControls(mesh.solverDict(D.name()))
            )
          : DEqn.solve();

        // Not Newton's products: each measures G(x) - x at its own x,
        // which relaxing would only scale, and about D's previous iterate,
        // which is not that x (so a case's relaxationFactors are not
        // taken there either)
        if (!newtonNow)
        {
            relaxation.relax(D);
        }

        return perf;
    };

    // Scalings of one update a step limit may ask for (each is measured
    // anew; with gaps linear along the update one suffices)
    const label maxStepLimits = 30;

    Info<< "\nStarting load stepping\n" << endl;

    while (runTime.loop())
    {
        label nCorr = 0;
        label nLinearStep = 0;
        scalar residual = GREAT;
        bool converged = false;
        bool multipliersExhausted = false;

        acceleration.reset();
        newtonLoop.reset();
        newtonNow = false;
        nSegregated = 0;

        do
        {
            const bool newtonBefore = newtonNow;
            newtonNow = newton && newtonLoop.newtonNext();
            if (newtonBefore && !newtonNow)
            {
                // From the last Newton iterate, a new history
                acceleration.reset();
            }
            nSegregated += (newton && newtonLoop.exhausted());

            D.storePrevIter();
            acceleration.storeIterate();
            if (newtonNow)
            {
                newtonLoop.storeIterate();
            }

            const SolverPerformance<vector> perf = solveD();
            checkDiverged(nCorr + 1);
            const label nLinear = cmptSum(perf.nIterations());
            nLinearStep += nLinear;

            // A component that stays at round-off against the displacement
            // (D_x of a uniaxial nu = 0 column) has a normalised residual
            // of pure noise: it is left out of the convergence measure
            const vector Dmax(gMax(cmptMag(D.primitiveField())));
            const scalar Dscale = cmptMax(Dmax);
            residual = 0;
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                if (Dmax[d] > residualFloor*Dscale)
                {
                    residual = max(residual, perf.initialResidual()[d]);
                }
            }

            ++nCorr;

            // The contact state entered this solve through the boundary
            // conditions; it counts as converged when it did not change
            // in this corrector
            converged =
                residual < tolerance
             && contactStateReporter::converged(D, tolerance);

            if (converged)
            {
                // A converged step keeps the state the test was made at
                if (newtonNow)
                {
                    newtonLoop.accept();
                }
                else
                {
                    acceleration.accept();
                }

                // Methods with stored multipliers update them now; while
                // they move the step goes on from this state, with a new
                // history (the map changed with them)
                if (contactStateReporter::updateMultipliers(D))
                {
                    converged = false;
                    acceleration.reset();
                    newtonLoop.restart();
                }
                else if (!contactStateReporter::multipliersConverged(D))
                {
                    converged = false;
                    multipliersExhausted = true;
                }
            }
            else if (newtonNow)
            {
                // The next iterate is x + d of a Newton step (or a shorter
                // trial along the last one), each product one corrector
                newtonLoop.step
                (
                    contactStateReporter::activeSetChanged(D),
                    [&]() -> label
                    {
                        updateStress();
                        const label n = cmptSum(solveD().nIterations());
                        nLinearStep += n;
                        return n;
                    }
                );
                nCorr += newtonLoop.lastProducts();
            }
            else
            {
                // The next iterate is the accelerated one (a new active
                // set starts a new history)
                const bool changed = contactStateReporter::activeSetChanged(D);
                if (newton && !newtonLoop.exhausted())
                {
                    newtonLoop.startCorrector(changed);
                }
                acceleration.accelerate(changed);
            }

            // A method that keeps every gap positive (barrier) limits the
            // update of the iterate actually kept (the solve's, the
            // accelerated or the accepted one): D moves back along it
            // until every such method admits it, measured anew each time
            // (a backtracking line search)
            for (label nLimit = 0; ; ++nLimit)
            {
                const scalar alpha =
                    contactStateReporter::stepLimit(D, newtonNow);
                if (alpha >= 1)
                {
                    break;
                }
                if (nLimit == maxStepLimits)
                {
                    FatalErrorInFunction
                        << "Load step at time " << runTime.timeName()
                        << ", corrector " << nCorr << ": the contact step"
                        << " limit still asks for " << alpha << " of the"
                        << " update after " << maxStepLimits << " scalings"
                        << exit(FatalError);
                }
                acceleration.scaleStep(alpha);
            }

            checkDiverged(nCorr);
            updateStress();

            if (verbose)
            {
                Info<< "    corrector " << nCorr
                    << "  residual = " << residual
                    << "  linear iterations = " << nLinear;
                if (newtonNow)
                {
                    Info<< "  products = " << newtonLoop.lastProducts()
                        << "  krylov residual = "
                        << newtonLoop.lastKrylovResidual();
                }
                else if (acceleration.active())
                {
                    Info<< "  |G(x) - x| = " << acceleration.residualNorm()
                        << "  columns = " << acceleration.nColumns();
                }
                Info<< endl;
            }
        }
        while (!converged && !multipliersExhausted && nCorr < nCorrectors);

        if (nonlinearGeometry)
        {
            // A converged state must be a deformation: nothing of a step
            // with a cell turned inside out is written
            checkAdmissible(gradD);
        }

        sigmaEq = sqrt((3.0/2.0)*magSqr(dev(sigma)));
        volPointInterpolation::New(mesh).interpolate(D, pointD);

        const string contactSummary(contactStateReporter::summary(D));

        Info<< "Time = " << runTime.timeName()
            << "  correctors = " << nCorr
            << "  residual = " << residual
            << (converged ? "" : "  NOT CONVERGED")
            << contactSummary.c_str()
            << endl;
        if (newton)
        {
            Info<< "    newtonKrylov: " << newtonLoop.nNewton()
                << " Newton steps, " << newtonLoop.nProducts()
                << " products, " << newtonLoop.nKrylovFailures()
                << " GMRES solves unconverged, after "
                << newtonLoop.nStart() << " segregated correctors";
            if (nSegregated)
            {
                Info<< ", then " << nSegregated << " segregated correctors"
                    << (
                           newtonLoop.stalled()
                         ? " from the best Newton iterate (Newton stalled:"
                           " no smaller residual in maxStalledSteps Newton"
                           " steps)"
                         : newtonLoop.abandoned()
                         ? " from the best Newton iterate (a Newton trial"
                           " ten times above its residual was rejected)"
                         : ""
                       );
            }
            Info<< endl;
        }
        Info<< "    linear solver: " << nLinearStep << " iterations over the"
            << " components, " << scalar(nLinearStep)/max(nCorr, 1)
            << " per corrector" << endl;

        // contactReport and other function objects read it
        mesh.data::set("solidMechanicsConverged", converged);

        if (!converged)
        {
            if (onNonConvergence == "stop")
            {
                // Nothing of this step is written: the last converged time
                // is the last on disk
                FatalErrorInFunction
                    << "Load step at time " << runTime.timeName()
                    << " did not converge in nCorrectors = " << nCorrectors
                    << ": residual " << residual << " (tolerance "
                    << tolerance << ")"
                    << (
                           multipliersExhausted
                         ? ", the contact multipliers did not converge in"
                           " the method's maximum number of updates"
                         : residual < tolerance
                         ? ", contact state still changing"
                         : ""
                       )
                    << nl << "Contact state:"
                    << (contactSummary.empty() ? " none" : contactSummary.c_str())
                    << nl << "Raise nCorrectors, or set 'onNonConvergence"
                    << " continue;' in solidMechanics of "
                    << solidControls.name() << " to accept such steps"
                    << exit(FatalError);
            }

            WarningInFunction
                << "Load step at time " << runTime.timeName()
                << " did not converge in nCorrectors = " << nCorrectors
                << " (residual " << residual << ", tolerance "
                << tolerance << "); going on (onNonConvergence continue)"
                << endl;
        }

        runTime.write();
    }

    Info<< nl << "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
        << "  ClockTime = " << runTime.elapsedClockTime() << " s"
        << nl << "End" << nl << endl;

    return 0;
}
