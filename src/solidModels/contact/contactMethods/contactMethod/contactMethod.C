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


void Foam::contactMethod::write(Ostream& os) const
{
    coeffs_.writeEntry(word(methodName() + "Coeffs"), os);
}
