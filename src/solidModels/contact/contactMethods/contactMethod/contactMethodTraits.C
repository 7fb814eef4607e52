/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactMethodTraits.H"
#include "IStringStream.H"
#include "OStringStream.H"

const Foam::Enum<Foam::contactMethodTraits::answerKind>
Foam::contactMethodTraits::answerKindNames
({
    { answerKind::exact, "exact" },
    { answerKind::penalty, "penalty" },
    { answerKind::constitutive, "constitutive" },
    { answerKind::barrier, "barrier" },
});


const Foam::Enum<Foam::contactMethodTraits::multiplierKind>
Foam::contactMethodTraits::multiplierKindNames
({
    { multiplierKind::none, "none" },
    { multiplierKind::augmented, "augmented" },
    { multiplierKind::regularised, "regularised" },
});


Foam::dictionary Foam::contactMethodTraits::defaults() const
{
    IStringStream is(defaultCoeffs ? defaultCoeffs : "");
    return dictionary(is);
}


Foam::string Foam::contactMethodTraits::describe() const
{
    OStringStream os;
    os  << "answer=" << answerKindNames[answer]
        << " openStart=" << (openStart ? "yes" : "no")
        << " slip=" << (allowsSlip ? "yes" : "no")
        << " multipliers=" << multiplierKindNames[multipliers]
        << " finiteStrain=" << (finiteStrain ? "yes" : "no")
        << " coeffs=";

    // key:value pairs, so that a line splits on white space into tokens
    const dictionary d(defaults());
    label n = 0;
    for (const entry& e : d)
    {
        os  << (n++ ? "," : "") << e.keyword() << ':';
        ITstream& value = e.stream();
        for (label i = 0; i < value.size(); ++i)
        {
            os  << (i ? "_" : "") << value[i];
        }
    }
    if (!n)
    {
        os  << '-';
    }
    return os.str();
}
