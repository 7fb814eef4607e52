/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactStateReporter.H"

Foam::string Foam::contactStateReporter::summary(const volVectorField& D)
{
    string s;
    forAll(D.boundaryField(), patchi)
    {
        const contactStateReporter* rep =
            dynamic_cast<const contactStateReporter*>
            (
                &D.boundaryField()[patchi]
            );

        if (rep)
        {
            // A master patch of a contact pair has nothing of its own
            const string state(rep->contactState());
            if (!state.empty())
            {
                s += "  [" + D.mesh().boundary()[patchi].name() + ": "
                   + state + "]";
            }
        }
    }
    return s;
}


bool Foam::contactStateReporter::converged
(
    const volVectorField& D,
    const scalar tolerance
)
{
    bool conv = true;
    forAll(D.boundaryField(), patchi)
    {
        const contactStateReporter* rep =
            dynamic_cast<const contactStateReporter*>
            (
                &D.boundaryField()[patchi]
            );

        // Every patch is asked, so that the reductions inside match on
        // all processors
        if (rep && !rep->contactConverged(tolerance))
        {
            conv = false;
        }
    }
    return conv;
}


bool Foam::contactStateReporter::activeSetChanged(const volVectorField& D)
{
    label changes = 0;
    for (const fvPatchVectorField& pf : D.boundaryField())
    {
        const contactStateReporter* rep =
            dynamic_cast<const contactStateReporter*>(&pf);
        if (rep)
        {
            changes += rep->activeSetChanges();
        }
    }
    return changes > 0;
}


void Foam::contactStateReporter::updateFromCells(volVectorField& D)
{
    for (fvPatchVectorField& pf : D.boundaryFieldRef())
    {
        contactStateReporter* rep = dynamic_cast<contactStateReporter*>(&pf);
        if (rep)
        {
            rep->updateFromCells();
        }
    }
}
