/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "outerCorrectorAcceleration.H"
#include "processorSum.H"
#include "Enum.H"
#include "fixedGradientFvPatchFields.H"
#include "contactStateReporter.H"

#include <stdexcept>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

enum class accelerationType { none, anderson };

const Foam::Enum<accelerationType> accelerationNames
({
    { accelerationType::none, "none" },
    { accelerationType::anderson, "anderson" }
});


} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::outerCorrectorAcceleration::gather(std::vector<double>& x) const
{
    x.clear();
    for (const vector& v : D_.primitiveField())
    {
        x.insert(x.end(), v.cdata(), v.cdata() + vector::nComponents);
    }
    for (const fvPatchVectorField& pf : D_.boundaryField())
    {
        if (!pf.coupled())
        {
            for (const vector& v : pf)
            {
                x.insert(x.end(), v.cdata(), v.cdata() + vector::nComponents);
            }
        }
    }
    // A contact method's multipliers updated in every corrector, each
    // divided by its scale (a stiffness) into a length like D's
    List<scalarField> scales;
    const List<scalarField*> states
    (
        contactStateReporter::acceleratedStates(D_, scales)
    );
    forAll(states, k)
    {
        forAll(*states[k], facei)
        {
            x.push_back((*states[k])[facei]/scales[k][facei]);
        }
    }
}


void Foam::outerCorrectorAcceleration::scatter(const std::vector<double>& x)
{
    std::size_t i = 0;
    for (vector& v : D_.primitiveFieldRef())
    {
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            v[d] = x[i++];
        }
    }

    // Coupled patches take the neighbours' new cells. Only they are
    // evaluated: evaluate() on a condition whose coefficients are not
    // current would run its update (a contact update) once more
    volVectorField::Boundary& bf = D_.boundaryFieldRef();
    // (all sends before all receives: a schedule is not needed)
    const Pstream::commsTypes comms =
        Pstream::defaultCommsType == Pstream::commsTypes::nonBlocking
      ? Pstream::commsTypes::nonBlocking
      : Pstream::commsTypes::blocking;
    for (fvPatchVectorField& pf : bf)
    {
        if (pf.coupled())
        {
            pf.initEvaluate(comms);
        }
    }
    if (comms == Pstream::commsTypes::nonBlocking)
    {
        Pstream::waitRequests();
    }
    for (fvPatchVectorField& pf : bf)
    {
        if (pf.coupled())
        {
            pf.evaluate(comms);
        }
    }

    for (fvPatchVectorField& pf : bf)
    {
        if (!pf.coupled())
        {
            vectorField v(pf.size());
            for (vector& vi : v)
            {
                for (direction d = 0; d < vector::nComponents; ++d)
                {
                    vi[d] = x[i++];
                }
            }
            if (isA<fixedGradientFvPatchVectorField>(pf))
            {
                // The gradient is the condition's state between correctors
                // (grad D takes its boundary normal part from it): it goes
                // with the face value, or the previous iterate's would stay
                fixedGradientFvPatchVectorField& fg =
                    refCast<fixedGradientFvPatchVectorField>(pf);
                fg.gradient() =
                    (v - fg.patchInternalField())*fg.patch().deltaCoeffs();
            }
            pf == v;
        }
    }

    List<scalarField> scales;
    const List<scalarField*> states
    (
        contactStateReporter::acceleratedStates(D_, scales)
    );
    forAll(states, k)
    {
        forAll(*states[k], facei)
        {
            (*states[k])[facei] = x[i++]*scales[k][facei];
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::outerCorrectorAcceleration::outerCorrectorAcceleration
(
    const dictionary& solidControls,
    volVectorField& D
)
:
    D_(D),
    anderson_()
{
    const word typeName
    (
        solidControls.getOrDefault<word>("acceleration", "anderson")
    );
    if (!accelerationNames.found(typeName))
    {
        FatalIOErrorInFunction(solidControls)
            << "Entry 'acceleration' = " << typeName << " in "
            << solidControls.name() << " is invalid: valid are "
            << "anderson (the default: Anderson acceleration, IQN-ILS, of"
            << " the outer correctors) and none (the plain iteration)"
            << exit(FatalIOError);
    }

    // The depth is checked whether or not it is used
    // 15 columns: hertzCylinder (LM) takes 64 correctors with 5, 52 with
    // 10, 50 with 15, 20 or 30 (plateHole 43, 38, 36, 36, 36); each column
    // holds two state vectors
    c4f::coupling::AndersonParameters p;

    // The kernel's own check of the parameters, reported against the
    // entry just read
    const auto checkEntry =
        [&](const word& entry, const string& value, const char* valid)
    {
        try
        {
            c4f::coupling::AndersonAcceleration::check(p);
        }
        catch (const std::invalid_argument&)
        {
            FatalIOErrorInFunction(solidControls)
                << "Entry '" << entry << "' = " << value.c_str() << " in "
                << solidControls.name() << " is invalid: " << valid
                << exit(FatalIOError);
        }
    };

    p.depth = solidControls.getOrDefault<label>("andersonDepth", 15);
    checkEntry
    (
        "andersonDepth",
        Foam::name(p.depth),
        "it must be an integer >= 1 (the difference columns kept; 15 by"
        " default)"
    );

    // A restart when an accelerated step made the residual grow by more
    // than this factor (none by default)
    if (solidControls.found("andersonRestartGrowth"))
    {
        p.restartGrowth =
            solidControls.get<scalar>("andersonRestartGrowth");
        checkEntry
        (
            "andersonRestartGrowth",
            Foam::name(p.restartGrowth),
            "it must be a number >= 1 (the history is cleared when an"
            " accelerated corrector's residual exceeds that factor times"
            " the one before; absent: never)"
        );
    }

    if (accelerationNames[typeName] == accelerationType::none)
    {
        return;
    }

    anderson_.reset
    (
        new c4f::coupling::AndersonAcceleration
        (
            p,
            processorSumReduction()
        )
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::outerCorrectorAcceleration::reset()
{
    if (anderson_)
    {
        anderson_->reset();
    }
}


void Foam::outerCorrectorAcceleration::storeIterate()
{
    // Also without acceleration: a limited step goes back towards x
    gather(x_);
}


void Foam::outerCorrectorAcceleration::accelerate(const bool restart)
{
    if (!anderson_)
    {
        return;
    }

    if (restart)
    {
        // D stays at G(x): the first step of the new history is plain
        anderson_->reset();
        return;
    }

    gather(g_);
    anderson_->update(x_, g_, xNext_);
    scatter(xNext_);
}


void Foam::outerCorrectorAcceleration::accept()
{
    if (anderson_)
    {
        scatter(x_);
    }
}


void Foam::outerCorrectorAcceleration::scaleStep(const scalar alpha)
{
    gather(g_);
    xNext_.resize(x_.size());
    for (std::size_t i = 0; i < x_.size(); ++i)
    {
        xNext_[i] = x_[i] + alpha*(g_[i] - x_[i]);
    }
    scatter(xNext_);
}
