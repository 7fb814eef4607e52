/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactStateReporter.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Call f(reporter, patchi) for every patch of D that reports, in patch
//  order (the same on every processor, so collective calls match)
template<class Reporter, class Boundary, class Fn>
void forEachReporter(Boundary& bf, Fn f)
{
    forAll(bf, patchi)
    {
        Reporter* rep = dynamic_cast<Reporter*>(&bf[patchi]);
        if (rep)
        {
            f(*rep, patchi);
        }
    }
}

//- Whether pred holds for a reporting patch of D on any processor
template<class Pred>
bool anyReporter(const Foam::volVectorField& D, Pred pred)
{
    bool any = false;
    forEachReporter<const Foam::contactStateReporter>
    (
        D.boundaryField(),
        [&](const Foam::contactStateReporter& rep, const Foam::label)
        {
            any = pred(rep) || any;
        }
    );
    Foam::reduce(any, Foam::orOp<bool>());
    return any;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::string Foam::contactStateReporter::summary(const volVectorField& D)
{
    string s;
    forEachReporter<const contactStateReporter>
    (
        D.boundaryField(),
        [&](const contactStateReporter& rep, const label patchi)
        {
            // A master patch of a contact pair has nothing of its own
            const string state(rep.contactState());
            if (!state.empty())
            {
                s += "  [" + D.mesh().boundary()[patchi].name() + ": "
                   + state + "]";
            }
        }
    );
    return s;
}


bool Foam::contactStateReporter::converged
(
    const volVectorField& D,
    const scalar tolerance
)
{
    // Every patch is asked, so that the reductions inside match on all
    // processors
    bool conv = true;
    forEachReporter<const contactStateReporter>
    (
        D.boundaryField(),
        [&](const contactStateReporter& rep, const label)
        {
            conv = rep.contactConverged(tolerance) && conv;
        }
    );
    return conv;
}


bool Foam::contactStateReporter::activeSetChanged(const volVectorField& D)
{
    label changes = 0;
    forEachReporter<const contactStateReporter>
    (
        D.boundaryField(),
        [&](const contactStateReporter& rep, const label)
        {
            changes += rep.activeSetChanges();
        }
    );
    return changes > 0;
}


bool Foam::contactStateReporter::updateMultipliers(volVectorField& D)
{
    bool updated = false;
    forEachReporter<contactStateReporter>
    (
        D.boundaryFieldRef(),
        [&](contactStateReporter& rep, const label)
        {
            updated = rep.updateMultipliers() || updated;
        }
    );
    return updated;
}


bool Foam::contactStateReporter::multipliersConverged
(
    const volVectorField& D
)
{
    bool conv = true;
    forEachReporter<const contactStateReporter>
    (
        D.boundaryField(),
        [&](const contactStateReporter& rep, const label)
        {
            conv = rep.multipliersConverged() && conv;
        }
    );
    return conv;
}


Foam::scalar Foam::contactStateReporter::stepLimit
(
    volVectorField& D,
    const bool newtonStep
)
{
    scalar alpha = 1;
    forEachReporter<contactStateReporter>
    (
        D.boundaryFieldRef(),
        [&](contactStateReporter& rep, const label)
        {
            alpha = min(rep.stepLimit(newtonStep), alpha);
        }
    );
    return alpha;
}


Foam::List<Foam::scalarField*> Foam::contactStateReporter::acceleratedStates
(
    volVectorField& D,
    List<scalarField>& scales
)
{
    DynamicList<scalarField*> states;
    DynamicList<scalarField> sc;
    forEachReporter<contactStateReporter>
    (
        D.boundaryFieldRef(),
        [&](contactStateReporter& rep, const label)
        {
            scalarField scale;
            scalarField* f = rep.acceleratedState(scale);
            if (f)
            {
                states.append(f);
                sc.append(scale);
            }
        }
    );
    scales = std::move(sc);
    return List<scalarField*>(std::move(states));
}


void Foam::contactStateReporter::saveCorrectorStates(volVectorField& D)
{
    forEachReporter<contactStateReporter>
    (
        D.boundaryFieldRef(),
        [](contactStateReporter& rep, const label)
        {
            rep.saveCorrectorState();
        }
    );
}


void Foam::contactStateReporter::restoreCorrectorStates
(
    volVectorField& D,
    const bool frozen
)
{
    forEachReporter<contactStateReporter>
    (
        D.boundaryFieldRef(),
        [frozen](contactStateReporter& rep, const label)
        {
            rep.restoreCorrectorState(frozen);
        }
    );
}


bool Foam::contactStateReporter::limitsSteps(const volVectorField& D)
{
    return anyReporter
    (
        D,
        [](const contactStateReporter& rep) { return rep.limitsSteps(); }
    );
}


// ************************************************************************* //
