/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactMethod.H"

namespace Foam
{
    defineTypeNameAndDebug(contactMethod, 0);
    defineRunTimeSelectionTable(contactMethod, dictionary);
}


Foam::contactMethod::contactMethod
(
    const fvPatch& patch,
    const dictionary& coeffs
)
:
    patch_(patch),
    coeffs_(coeffs),
    state_(patch.size())
{}


Foam::contactMethod::traitsTable& Foam::contactMethod::traitsTableRef()
{
    static traitsTable table;
    return table;
}


const Foam::contactMethodTraits& Foam::contactMethod::traits
(
    const word& name
)
{
    const auto iter = traitsTableRef().cfind(name);
    if (!iter.found())
    {
        FatalErrorInFunction
            << "Contact method " << name << " has no traits: its .C must"
            << " register it with addContactMethodToTables(" << name << ")"
            << abort(FatalError);
    }
    return **iter;
}


void Foam::contactMethod::printTable(std::ostream& os)
{
    for (const word& name : dictionaryConstructorTablePtr_->sortedToc())
    {
        os  << name << ' ' << traits(name).describe().c_str() << '\n';
    }
}


void Foam::contactMethod::write(Ostream& os) const
{
    coeffs_.writeEntry(word(methodName() + "Coeffs"), os);
}
