/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "newtonKrylovCorrector.H"
#include "processorSum.H"
#include "contactStateReporter.H"
#include "Enum.H"
#include "Switch.H"

#include <cmath>
#include <stdexcept>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

enum class algorithmType { segregated, newtonKrylov };

const Foam::Enum<algorithmType> algorithmNames
({
    { algorithmType::segregated, "segregated" },
    { algorithmType::newtonKrylov, "newtonKrylov" }
});


double globalNorm(const std::vector<double>& v)
{
    double s = 0;
    for (const double vi : v)
    {
        s += vi*vi;
    }
    Foam::reduce(s, Foam::sumOp<double>());
    return std::sqrt(s);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * * //

bool Foam::newtonKrylovCorrector::selected(const dictionary& solidControls)
{
    const word name
    (
        solidControls.getOrDefault<word>("algorithm", "segregated")
    );
    if (!algorithmNames.found(name))
    {
        FatalIOErrorInFunction(solidControls)
            << "Entry 'algorithm' = " << name << " in "
            << solidControls.name() << " is invalid: valid are "
            << "segregated (the default: outer correctors, accelerated"
            << " as 'acceleration' says) and newtonKrylov (Jacobian-free"
            << " Newton-Krylov on the correctors)"
            << exit(FatalIOError);
    }
    return algorithmNames[name] == algorithmType::newtonKrylov;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::newtonKrylovCorrector::newtonKrylovCorrector
(
    const dictionary& solidControls,
    volVectorField& D
)
:
    D_(D),
    state_(D),
    gmres_(),
    linearIterations_(2),
    fdStep_(1e-9),
    maxBacktracks_(4),
    maxNewtonSteps_(50),
    maxStalledSteps_(8),
    maxSegregatedStart_(30),
    nStart_(0),
    settled_(false),
    substituted_(false),
    backtrackOnChange_(true),
    forcing_(forcingMode::always),
    normPrevious_(0),
    etaPrevious_(0),
    normBase_(0),
    normBest_(GREAT),
    nBest_(0),
    abandoned_(false),
    stalled_(false),
    alpha_(1),
    nBacktracks_(0),
    nNewton_(0),
    nProducts_(0),
    nKrylovFailures_(0),
    lastProducts_(0),
    lastKrylovResidual_(0)
{
    const dictionary& coeffs =
        solidControls.optionalSubDict("newtonKrylovCoeffs");

    const auto bad = [&](const word& entry, const string& value, const char* valid)
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry '" << entry << "' = " << value.c_str() << " in "
            << coeffs.name() << " is invalid: " << valid
            << exit(FatalIOError);
    };

    // An integer entry with its lower bound
    const auto readCount =
        [&](const word& entry, const label def, const label min, const char* what)
    {
        const label v = coeffs.getOrDefault<label>(entry, def);
        if (v < min)
        {
            bad
            (
                entry, Foam::name(v),
                (
                    "it must be an integer >= " + Foam::name(min) + " ("
                  + what + "; " + Foam::name(def) + " by default)"
                ).c_str()
            );
        }
        return v;
    };

    linearIterations_ = readCount
    (
        "linearIterations", 2, 1, "the GAMG cycles of every corrector's solve"
    );

    c4f::coupling::GmresParameters p;
    p.relativeTolerance = coeffs.getOrDefault<scalar>("krylovTolerance", 1e-3);
    p.maxIterations = coeffs.getOrDefault<label>("maxKrylov", 100);
    try
    {
        c4f::coupling::Gmres::check(p);
    }
    catch (const std::invalid_argument&)
    {
        const bool tol = !(p.relativeTolerance > 0 && p.relativeTolerance < 1);
        bad
        (
            tol ? "krylovTolerance" : "maxKrylov",
            tol ? Foam::name(p.relativeTolerance) : Foam::name(p.maxIterations),
            tol
          ? "it must lie in (0, 1) (GMRES's relative tolerance of each"
            " Newton correction; 0.001 by default)"
          : "it must be an integer >= 1 (the products, each one corrector,"
            " of a Newton step; 100 by default)"
        );
    }

    fdStep_ = coeffs.getOrDefault<scalar>("finiteDifferenceStep", 1e-9);
    if (!(fdStep_ > 0 && fdStep_ < 1e-2))
    {
        bad
        (
            "finiteDifferenceStep", Foam::name(fdStep_),
            "it must lie in (0, 0.01) (the finite-difference step relative"
            " to |x|; 1e-9 by default)"
        );
    }

    maxBacktracks_ = readCount
    (
        "maxBacktracks", 4, 0, "the line search's halvings"
    );

    maxNewtonSteps_ = readCount
    (
        "maxNewtonSteps", 50, 1,
        "the Newton steps of a load step before it goes on with the"
        " segregated correctors"
    );

    maxStalledSteps_ = readCount
    (
        "maxStalledSteps", 8, 1,
        "the Newton steps without a new smallest residual of the load step"
        " before it goes on with the segregated correctors from the best"
        " iterate"
    );

    maxSegregatedStart_ = readCount
    (
        "maxSegregatedStart", 30, 1,
        "the segregated correctors a load step starts with at most; Newton"
        " takes over after the first that leaves the contact state"
        " unchanged"
    );

    backtrackOnChange_ =
        coeffs.getOrDefault<bool>("backtrackOnChange", true);
    // yes / no, or the Eisenstat-Walker forcing on the Newton steps whose
    // corrector changed the contact state only
    const word forcing = coeffs.getOrDefault<word>("adaptiveForcing", "yes");
    if (forcing == "whileChanging")
    {
        forcing_ = forcingMode::whileChanging;
    }
    else if (Switch(forcing, true).valid())
    {
        forcing_ =
            Switch(forcing, true) ? forcingMode::always : forcingMode::never;
    }
    else
    {
        bad
        (
            "adaptiveForcing", forcing,
            "valid are yes (the Eisenstat-Walker forcing on every Newton"
            " step, the default), whileChanging (on the steps whose"
            " corrector changed the contact state, krylovTolerance on the"
            " others) and no (krylovTolerance throughout)"
        );
    }

    gmres_.reset(new c4f::coupling::Gmres(p, processorSumReduction()));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::dictionary& Foam::newtonKrylovCorrector::solverControls
(
    const dictionary& userControls
) const
{
    if (controls_.valid())
    {
        return controls_();
    }
    controls_.reset(new dictionary(userControls));
    dictionary& d = controls_();

    // A Krylov solver's iterations are not a linear map of the residual
    // (its step lengths are ratios of inner products of it), so its
    // products would not be the derivatives of one map: with PCG, GMRES
    // stalled at 0.1 to 0.5 of the residual on rigidSphere and rigidPunch
    // (the only tutorials with PCG). GAMG with a Gauss-Seidel smoother
    // instead: rigidSphere then takes 6 or 7 Newton steps a load step
    static const wordList krylov({"PCG", "PBiCG", "PBiCGStab", "PPCG", "PPCR"});
    const word solver(userControls.getOrDefault<word>("solver", word::null));
    if (krylov.found(solver))
    {
        d.clear();
        d.add("solver", "GAMG");
        d.add("smoother", "GaussSeidel");
        if (!substituted_)
        {
            substituted_ = true;
            Info<< "newtonKrylov: the D solver " << solver << " of "
                << userControls.name() << " is a Krylov solver, not a linear"
                << " map in a fixed number of iterations; Newton's"
                << " correctors solve with GAMG (smoother GaussSeidel)"
                << endl;
        }
    }

    d.set("tolerance", 0.0);
    d.set("relTol", 0.0);
    d.set("maxIter", linearIterations_);
    d.set("minIter", linearIterations_);
    // GAMG's scaling of each coarse correction is a ratio of inner products
    // of the residual: a nonlinear map, whose finite differences are not
    // the products of one linear preconditioner (plateHole, krylovTolerance
    // 1e-6: six Newton steps with it, two without). The coarsest level's
    // Krylov solve runs to round-off with the zero tolerances above, which
    // is linear to round-off (LU there does not take the contact
    // interface)
    d.set("scaleCorrection", false);
    return d;
}


void Foam::newtonKrylovCorrector::reset()
{
    controls_.clear();
    nStart_ = 0;
    settled_ = false;
    normPrevious_ = 0;
    etaPrevious_ = 0;
    xBase_.clear();
    dBase_.clear();
    normBase_ = 0;
    xBest_.clear();
    normBest_ = GREAT;
    nBest_ = 0;
    abandoned_ = false;
    stalled_ = false;
    alpha_ = 1;
    nBacktracks_ = 0;
    nNewton_ = 0;
    nProducts_ = 0;
    nKrylovFailures_ = 0;
    lastProducts_ = 0;
    lastKrylovResidual_ = 0;
}


void Foam::newtonKrylovCorrector::storeIterate()
{
    state_.gather(x_);
}


void Foam::newtonKrylovCorrector::step
(
    const bool changed,
    const std::function<label()>& corrector
)
{
    lastProducts_ = 0;

    state_.gather(g_);
    const std::size_t n = x_.size();
    F_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        F_[i] = g_[i] - x_[i];
    }
    const scalar normF = globalNorm(F_);

    // Line search along the last correction, also where the corrector at
    // the trial changed the active set (backtrackOnChange: a step from a
    // poor set overshoots, see the header)
    if
    (
        (!changed || backtrackOnChange_)
     && !dBase_.empty()
     && nBacktracks_ < maxBacktracks_
     && !(normF <= (1 - 1e-4*alpha_)*normBase_)
    )
    {
        ++nBacktracks_;
        alpha_ *= 0.5;
        contactStateReporter::restoreCorrectorStates(D_, false);
        xp_.resize(n);
        for (std::size_t i = 0; i < n; ++i)
        {
            xp_[i] = xBase_[i] + alpha_*dBase_[i];
        }
        state_.scatter(xp_);
        return;
    }

    // Nonmonotone acceptance (the header): a trial the line search leaves
    // ten times above the best Newton iterate of this load step is not a
    // point to go on from; the segregated correctors take over from the
    // best iterate
    // (written so that a NaN |F|, a trial past J < 0, is rejected too)
    if (!dBase_.empty() && !xBest_.empty() && !(normF <= 10*normBest_))
    {
        abandoned_ = true;
        contactStateReporter::restoreCorrectorStates(D_, false);
        state_.scatter(xBest_);
        return;
    }
    if (normF < normBest_)
    {
        normBest_ = normF;
        xBest_ = x_;
        nBest_ = nNewton_;
    }
    else if (!xBest_.empty() && nNewton_ - nBest_ >= maxStalledSteps_)
    {
        // Stalled (see the header): the residual has not gone below its
        // best for maxStalledSteps Newton steps
        stalled_ = true;
        abandoned_ = true;
        contactStateReporter::restoreCorrectorStates(D_, false);
        state_.scatter(xBest_);
        return;
    }

    // A Newton step from x with the decisions its corrector took
    ++nNewton_;
    contactStateReporter::saveCorrectorStates(D_);

    // G(x) once more from the state every product starts from: a
    // corrector also depends on what the one before left besides x (the
    // contact faces' values and coefficients), and a difference of two
    // correctors from different such states would not vanish with eps
    // (finiteStrainPatchTest: without it, a 'converged' state 2 off in
    // sigma_yy)
    contactStateReporter::restoreCorrectorStates(D_, true);
    state_.scatter(x_);
    corrector();
    ++lastProducts_;
    state_.gather(g_);
    for (std::size_t i = 0; i < n; ++i)
    {
        F_[i] = g_[i] - x_[i];
    }

    const scalar xNorm = globalNorm(x_);
    const scalar eps = fdStep_*max(max(xNorm, globalNorm(F_)), VSMALL);

    const c4f::coupling::Gmres::Operator product =
        [&](const std::vector<double>& v, std::vector<double>& y)
        {
            contactStateReporter::restoreCorrectorStates(D_, true);
            xp_.resize(n);
            for (std::size_t i = 0; i < n; ++i)
            {
                xp_[i] = x_[i] + eps*v[i];
            }
            state_.scatter(xp_);
            corrector();
            state_.gather(gp_);
            ++lastProducts_;
            y.resize(n);
            for (std::size_t i = 0; i < n; ++i)
            {
                y[i] = v[i] - (gp_[i] - g_[i])/eps;
            }
        };

    // The forcing term: Eisenstat & Walker's (1996, SIAM J. Sci. Comput.
    // 17:16, choice 2 with gamma 0.9, alpha 2 and their safeguard), between
    // krylovTolerance and 0.1: a loose solve while the residual falls
    // slowly (far from the solution, or on a changing active set), a tight
    // one as Newton's convergence sets in
    const scalar tolMin = gmres_->parameters().relativeTolerance;
    const scalar maxForcing = 0.1;
    scalar eta = tolMin;
    // Not with a method that limits the updates (the barrier keeping its
    // gaps open): its loose first steps led hertzCylinder's gaps to
    // 1e-15 m, step after cut step, then a product closed one (with
    // krylovTolerance throughout, 24 Newton steps). With whileChanging
    // not where the corrector at x left the contact state as it was:
    // shallowIroning at t = 1.14 took 12 Newton steps with choice 2, its
    // residual 3e-5, 5e-5, 9e-5, 8e-5 over four of them of eta 0.06 to
    // 0.1 while the set stood still, 10 with it (see the header)
    const bool adaptive =
        (
            forcing_ == forcingMode::always
         || (forcing_ == forcingMode::whileChanging && changed)
        )
     && !contactStateReporter::limitsSteps(D_);
    if (adaptive && normPrevious_ > 0)
    {
        const scalar ratio = normF/normPrevious_;
        scalar e = 0.9*ratio*ratio;
        const scalar safeguard = 0.9*etaPrevious_*etaPrevious_;
        if (safeguard > 0.1)
        {
            e = max(e, safeguard);
        }
        eta = min(max(e, tolMin), maxForcing);
    }
    else if (adaptive)
    {
        eta = max(tolMin, maxForcing);
    }
    normPrevious_ = normF;
    etaPrevious_ = eta;

    std::vector<double> d;
    const c4f::coupling::GmresResult r = gmres_->solve(product, F_, d, eta);
    nProducts_ += lastProducts_;
    lastKrylovResidual_ = r.residualNorm/max(r.initialNorm, VSMALL);
    if (!r.converged)
    {
        ++nKrylovFailures_;
    }

    // The next corrector starts from this step's decisions at x + d and
    // takes its own
    contactStateReporter::restoreCorrectorStates(D_, false);
    xBase_ = x_;
    dBase_ = std::move(d);
    normBase_ = normF;
    alpha_ = 1;
    nBacktracks_ = 0;
    xp_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        xp_[i] = xBase_[i] + dBase_[i];
    }
    state_.scatter(xp_);
}


void Foam::newtonKrylovCorrector::accept()
{
    state_.scatter(x_);
}


// ************************************************************************* //
