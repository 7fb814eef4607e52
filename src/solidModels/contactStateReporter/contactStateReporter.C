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
            s += "  [" + D.mesh().boundary()[patchi].name() + ": "
               + rep->contactState() + "]";
        }
    }
    return s;
}
