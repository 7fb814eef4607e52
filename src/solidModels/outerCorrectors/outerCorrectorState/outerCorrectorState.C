/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "outerCorrectorState.H"
#include "fixedGradientFvPatchFields.H"
#include "contactStateReporter.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::outerCorrectorState::gather(std::vector<double>& x) const
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


void Foam::outerCorrectorState::scatter(const std::vector<double>& x)
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


// ************************************************************************* //
