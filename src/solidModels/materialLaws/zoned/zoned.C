/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "zoned.H"
#include "IOdictionary.H"
#include "IFstream.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace solidMaterialLaws
{
    defineTypeNameAndDebug(zoned, 0);
    addToRunTimeSelectionTable(solidMaterialLaw, zoned, dictionary);
}
}


namespace
{

//- The keyword of the law of the cells in no listed zone
const Foam::word defaultKey("default");

//- Copy the entries of `from` whose law is lawi into `to`
template<class Type>
void pickLaw
(
    const Foam::label lawi,
    const Foam::labelUList& law,
    const Foam::UList<Type>& from,
    Foam::UList<Type>& to
)
{
    forAll(law, i)
    {
        if (law[i] == lawi)
        {
            to[i] = from[i];
        }
    }
}

//- Each law on the whole volume field, kept where it holds: the laws stay
//  unaware of the zones, at the cost of one evaluation per law
template<class Type, class Eval>
void pickVolField
(
    const Foam::PtrList<Foam::solidMaterialLaw>& laws,
    const Foam::labelUList& cellLaw,
    const Foam::List<Foam::labelList>& patchLaw,
    const Eval& eval,
    Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>& to
)
{
    forAll(laws, lawi)
    {
        const auto tfrom(eval(laws[lawi]));
        pickLaw(lawi, cellLaw, tfrom().primitiveField(), to.primitiveFieldRef());
        forAll(to.boundaryField(), patchi)
        {
            pickLaw
            (
                lawi, patchLaw[patchi], tfrom().boundaryField()[patchi],
                to.boundaryFieldRef()[patchi]
            );
        }
    }
}

} // End anonymous namespace


void Foam::solidMaterialLaws::zoned::checkNoDuplicates
(
    const dictionary& dict
) const
{
    const IOdictionary* file = dynamic_cast<const IOdictionary*>(&dict);
    if (!file)
    {
        return;
    }

    // The file once more, read as it is (operator>> would reset the mode
    // to merge); OpenFOAM's own error names the keyword, file and line.
    // The master reads it and stops every processor on an error.
    const entry::inputMode mode = entry::globalInputMode;
    entry::globalInputMode = entry::inputMode::ERROR;
    if (Pstream::master())
    {
        IFstream is(file->filePath());
        dictionary strict;
        strict.read(is);
    }
    entry::globalInputMode = mode;
}


void Foam::solidMaterialLaws::zoned::assignLaws()
{
    const cellZoneMesh& zones = mesh_.cellZones();

    DynamicList<label> zoneIDs;
    label defaultLaw = -1;

    for (const entry& e : coeffs_)
    {
        const word key(e.keyword());

        if (e.keyword().isPattern())
        {
            FatalIOErrorInFunction(coeffs_)
                << "Entry '" << key << "' in " << coeffs_.name()
                << " is a pattern: name each cellZone literally."
                << " Valid cellZones: " << zones.sortedNames()
                << exit(FatalIOError);
        }

        const label zonei = (key == defaultKey) ? -1 : zones.findZoneID(key);
        if (key != defaultKey && zonei < 0)
        {
            FatalIOErrorInFunction(coeffs_)
                << "Entry '" << key << "' in " << coeffs_.name()
                << " is not a cellZone of the mesh. Valid cellZones: "
                << zones.sortedNames() << " and '" << defaultKey
                << "' for the cells in no listed zone"
                << exit(FatalIOError);
        }

        if (!e.isDict() || !e.dict().found("materialLaw"))
        {
            FatalIOErrorInFunction(coeffs_)
                << "Entry '" << key << "' in " << coeffs_.name()
                << " has no law: it must be a dictionary with"
                << " 'materialLaw <law>;' and '<law>Coeffs { ... }'"
                << exit(FatalIOError);
        }

        const word lawType(e.dict().get<word>("materialLaw"));
        if (lawType == typeName)
        {
            FatalIOErrorInFunction(e.dict())
                << "Entry '" << key << "' in " << coeffs_.name()
                << " selects materialLaw " << typeName << ": a zone's law"
                << " must be one of the other laws"
                << exit(FatalIOError);
        }

        Info<< "    " << key << ": ";
        laws_.append(solidMaterialLaw::New(mesh_, e.dict()));
        lawNames_.append(key);

        if (key == defaultKey)
        {
            defaultLaw = laws_.size() - 1;
            zoneIDs.append(-1);
        }
        else
        {
            zoneIDs.append(zonei);
        }
    }

    if (laws_.empty())
    {
        FatalIOErrorInFunction(coeffs_)
            << coeffs_.name() << " lists no law: give one entry per"
            << " cellZone (valid: " << zones.sortedNames() << ") and"
            << " optionally '" << defaultKey << "'"
            << exit(FatalIOError);
    }

    // The default goes last, so that a listed zone always wins
    cellLaw_.setSize(mesh_.nCells(), -1);
    forAll(laws_, lawi)
    {
        if (zoneIDs[lawi] < 0)
        {
            continue;
        }
        const labelList& cells = zones[zoneIDs[lawi]];

        label nShared = 0;
        label other = -1;
        for (const label celli : cells)
        {
            if (cellLaw_[celli] >= 0)
            {
                ++nShared;
                other = cellLaw_[celli];
            }
            else
            {
                cellLaw_[celli] = lawi;
            }
        }

        // Every processor stops, or none
        other = returnReduce(other, maxOp<label>());
        if (returnReduce(nShared, sumOp<label>()) > 0)
        {
            FatalIOErrorInFunction(coeffs_)
                << "Entries '" << lawNames_[other] << "' and '"
                << lawNames_[lawi] << "' in " << coeffs_.name()
                << " are overlapping cellZones: they share "
                << returnReduce(nShared, sumOp<label>())
                << " cells, which would have two laws"
                << exit(FatalIOError);
        }
    }

    label nFree = 0;
    forAll(cellLaw_, celli)
    {
        if (cellLaw_[celli] < 0)
        {
            ++nFree;
            cellLaw_[celli] = defaultLaw;
        }
    }
    reduce(nFree, sumOp<label>());

    if (nFree > 0 && defaultLaw < 0)
    {
        FatalIOErrorInFunction(coeffs_)
            << nFree << " cells of the mesh are in no cellZone listed in "
            << coeffs_.name() << " (listed: " << lawNames_ << ", cellZones"
            << " of the mesh: " << zones.sortedNames() << "): list their"
            << " zone or give a '" << defaultKey << "' law"
            << exit(FatalIOError);
    }

    forAll(laws_, lawi)
    {
        label n = 0;
        for (const label l : cellLaw_)
        {
            n += (l == lawi);
        }
        Info<< "    " << lawNames_[lawi] << ": " << returnReduce(n, sumOp<label>())
            << " cells, materialLaw " << laws_[lawi].type() << endl;
    }
}


void Foam::solidMaterialLaws::zoned::setPatchLaws()
{
    // Across a coupled patch the neighbour's law comes with the field swap
    tmp<volScalarField> tlawField
    (
        uniformField("zonedLaw", dimensionedScalar(dimless, Zero))
    );
    volScalarField& lawField = tlawField.ref();
    forAll(cellLaw_, celli)
    {
        lawField[celli] = cellLaw_[celli];
    }
    lawField.correctBoundaryConditions();

    patchLaw_.setSize(mesh_.boundary().size());
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatchScalarField& pf = lawField.boundaryField()[patchi];
        const scalarField values
        (
            pf.coupled() ? pf.patchNeighbourField() : pf.patchInternalField()
        );
        labelList& law = patchLaw_[patchi];
        law.setSize(values.size());
        forAll(values, facei)
        {
            law[facei] = label(values[facei] + 0.5);
        }
    }
}


Foam::solidMaterialLaws::zoned::zoned
(
    const word& lawType,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    solidMaterialLaw(lawType, mesh, dict),
    laws_(),
    lawNames_(),
    cellLaw_(),
    patchLaw_()
{
    checkNoDuplicates(dict);
    assignLaws();
    setPatchLaws();
}


Foam::tmp<Foam::volScalarField>
Foam::solidMaterialLaws::zoned::impK() const
{
    tmp<volScalarField> tK
    (
        uniformField("impK", dimensionedScalar(dimPressure, Zero))
    );
    volScalarField& K = tK.ref();

    forAll(laws_, lawi)
    {
        const tmp<volScalarField> tKi(laws_[lawi].impK());
        pickLaw(lawi, cellLaw_, tKi().primitiveField(), K.primitiveFieldRef());
        forAll(K.boundaryField(), patchi)
        {
            pickLaw
            (
                lawi, patchLaw_[patchi], tKi().boundaryField()[patchi],
                K.boundaryFieldRef()[patchi]
            );
        }
    }

    return tK;
}


Foam::tmp<Foam::scalarField>
Foam::solidMaterialLaws::zoned::impK(const label patchi) const
{
    tmp<scalarField> tK(new scalarField(mesh_.boundary()[patchi].size(), 0));
    forAll(laws_, lawi)
    {
        pickLaw(lawi, patchLaw_[patchi], laws_[lawi].impK(patchi)(), tK.ref());
    }
    return tK;
}


Foam::tmp<Foam::volSymmTensorField>
Foam::solidMaterialLaws::zoned::sigma(const volTensorField& gradD) const
{
    tmp<volSymmTensorField> tsigma
    (
        uniformField("sigmaLaw", dimensionedSymmTensor(dimPressure, Zero))
    );
    pickVolField
    (
        laws_, cellLaw_, patchLaw_,
        [&gradD](const solidMaterialLaw& law) { return law.sigma(gradD); },
        tsigma.ref()
    );

    return tsigma;
}


Foam::tmp<Foam::symmTensorField>
Foam::solidMaterialLaws::zoned::sigma
(
    const tensorField& gradD,
    const label patchi
) const
{
    tmp<symmTensorField> ts(new symmTensorField(gradD.size(), Zero));
    forAll(laws_, lawi)
    {
        pickLaw
        (
            lawi, patchLaw_[patchi], laws_[lawi].sigma(gradD, patchi)(),
            ts.ref()
        );
    }
    return ts;
}


Foam::tmp<Foam::volTensorField>
Foam::solidMaterialLaws::zoned::firstPiola(const volTensorField& gradD) const
{
    tmp<volTensorField> tP
    (
        uniformField("firstPiolaLaw", dimensionedTensor(dimPressure, Zero))
    );
    pickVolField
    (
        laws_, cellLaw_, patchLaw_,
        [&gradD](const solidMaterialLaw& law) { return law.firstPiola(gradD); },
        tP.ref()
    );
    return tP;
}


Foam::tmp<Foam::tensorField>
Foam::solidMaterialLaws::zoned::firstPiola
(
    const tensorField& gradD,
    const label patchi
) const
{
    tmp<tensorField> tP(new tensorField(gradD.size(), Zero));
    forAll(laws_, lawi)
    {
        pickLaw
        (
            lawi, patchLaw_[patchi], laws_[lawi].firstPiola(gradD, patchi)(),
            tP.ref()
        );
    }
    return tP;
}


bool Foam::solidMaterialLaws::zoned::needsNonlinearGeometry() const
{
    forAll(laws_, lawi)
    {
        if (laws_[lawi].needsNonlinearGeometry())
        {
            return true;
        }
    }
    return false;
}


void Foam::solidMaterialLaws::zoned::checkGeometry
(
    const bool nonlinearGeometry,
    const dictionary& where
) const
{
    forAll(laws_, lawi)
    {
        laws_[lawi].checkGeometry(nonlinearGeometry, where);
    }
}


Foam::tmp<Foam::labelField>
Foam::solidMaterialLaws::zoned::cellMaterials() const
{
    return tmp<labelField>(new labelField(cellLaw_));
}
