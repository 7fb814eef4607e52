/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "outerCorrectorAcceleration.H"
#include "processorSum.H"
#include "Enum.H"

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

const Foam::Enum<Foam::outerCorrectorAcceleration::onActiveSetChange>
    onChangeNames
({
    { Foam::outerCorrectorAcceleration::onActiveSetChange::restart, "restart" },
    { Foam::outerCorrectorAcceleration::onActiveSetChange::secant, "secant" }
});


} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::outerCorrectorAcceleration::outerCorrectorAcceleration
(
    const dictionary& solidControls,
    volVectorField& D
)
:
    state_(D),
    anderson_(),
    onChange_(onActiveSetChange::restart)
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

    // What a changed active set does to the history (checked whether or
    // not it is used, as the depth)
    const word onChangeName
    (
        solidControls.getOrDefault<word>("andersonActiveSetChange", "restart")
    );
    if (!onChangeNames.found(onChangeName))
    {
        FatalIOErrorInFunction(solidControls)
            << "Entry 'andersonActiveSetChange' = " << onChangeName << " in "
            << solidControls.name() << " is invalid: valid are restart (the"
            << " default: the history and the last iterate are dropped) and"
            << " secant (the columns are dropped, the last iterate kept)"
            << exit(FatalIOError);
    }
    onChange_ = onChangeNames[onChangeName];

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
    state_.gather(x_);
}


void Foam::outerCorrectorAcceleration::accelerate(const bool restart)
{
    if (!anderson_)
    {
        return;
    }

    if (restart)
    {
        if (onChange_ == onActiveSetChange::restart)
        {
            // D stays at G(x): the first step of the new history is plain
            anderson_->reset();
            return;
        }

        // The step from x is the secant through the change alone
        anderson_->clearColumns();
    }

    state_.gather(g_);
    anderson_->update(x_, g_, xNext_);
    state_.scatter(xNext_);
}


void Foam::outerCorrectorAcceleration::accept()
{
    if (anderson_)
    {
        state_.scatter(x_);
    }
}


void Foam::outerCorrectorAcceleration::scaleStep(const scalar alpha)
{
    state_.gather(g_);
    xNext_.resize(x_.size());
    for (std::size_t i = 0; i < x_.size(); ++i)
    {
        xNext_[i] = x_[i] + alpha*(g_[i] - x_[i]);
    }
    state_.scatter(xNext_);
}
