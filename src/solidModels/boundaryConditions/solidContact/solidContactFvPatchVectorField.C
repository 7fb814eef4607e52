/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "solidContactFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "solidPatchTractions.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::solidContactFvPatchVectorField&
Foam::solidContactFvPatchVectorField::shadow() const
{
    if (settings_.selfContact())
    {
        return *this;
    }

    const label shadowi =
        patch().boundaryMesh().findPatchID(shadowPatchName());

    const volVectorField& D =
        db().lookupObject<volVectorField>(internalField().name());

    const solidContactFvPatchVectorField* sp =
        isA<solidContactFvPatchVectorField>(D.boundaryField()[shadowi])
      ? &refCast<const solidContactFvPatchVectorField>
        (
            D.boundaryField()[shadowi]
        )
      : nullptr;

    if
    (
        !sp
     || sp->shadowPatchName() != patch().name()
     || sp->master() == master()
    )
    {
        FatalIOErrorInFunction(settings_.dict())
            << "The shadowPatch " << shadowPatchName() << " of "
            << settings_.dict().name() << " must be a solidContact patch of "
            << internalField().name() << " whose shadowPatch is "
            << patch().name() << ", with the other value of 'master'"
            << exit(FatalIOError);
    }
    return *sp;
}


const Foam::contactInterfaceCoupling*
Foam::solidContactFvPatchVectorField::coupling() const
{
    // A copy of the field (a previous iterate) has no pair of its own
    if (master() && !db().foundObject<volVectorField>(internalField().name()))
    {
        return nullptr;
    }
    const solidContactFvPatchVectorField& slave = master() ? shadow() : *this;
    return slave.corrector_.valid() ? &slave.corrector_.coupling() : nullptr;
}


Foam::tmp<Foam::vectorField>
Foam::solidContactFvPatchVectorField::assemblyForce(const vectorField& D)
{
    scalarField ps;
    return contactForce(D, ps, true);
}


Foam::tmp<Foam::vectorField>
Foam::solidContactFvPatchVectorField::contactForce
(
    const vectorField& D,
    scalarField& ps,
    const bool assembly
)
{
    vectorField Fs, Fm;
    coupling()->forces(D, Fs, Fm, ps, assembly);
    if (settings_.selfContact())
    {
        // Both roles on the same faces: each face's own law and the
        // reaction of the faces that press on it
        return Fs + Fm;
    }
    return tmp<vectorField>(new vectorField(master() ? Fm : Fs));
}


void Foam::solidContactFvPatchVectorField::setCoefficients
(
    const vectorField& F,
    const vectorField& diag
)
{
    const scalarField KS(solidPatchTractions::impK(patch())*patch().magSf());

    // The Laplacian's boundary flux is intCoeffs D_P - bouCoeffs plus the
    // interface's sum_j a n_k^2 D_j. fvMatrix::solveSegregated adds the
    // bouCoeffs of a non-coupled patch to the source and then the
    // interface's sum at the current D once more (it is meant to cancel a
    // coupled patch's patchNeighbourField term); so bouCoeffs carries
    // that sum with the other sign: with F = sum_j a ((D_j - D_P).n + b) n
    // at the current D, F + diag D_P is the explicit part plus that sum.
    gradInternal_ = -diag/KS;
    gradBoundary_ =
        (
            F
          + cmptMultiply(diag, patchInternalField())
          - history_.explicitTraction()*patch().magSf()
        )/KS;

    gradient() =
        (F/patch().magSf() - history_.explicitTraction())
       /solidPatchTractions::impK(patch());
}


void Foam::solidContactFvPatchVectorField::updateFromCells()
{
    if (coupling())
    {
        scalarField ps;
        const vectorField F(contactForce(primitiveField(), ps));
        vectorField& t = history_.traction();
        t = F/patch().magSf();
        gradient() =
            (t - history_.explicitTraction())
           /solidPatchTractions::impK(patch());

        // Self-contact: the pressure of the face's own law (its slave
        // part), which the method and the convergence test follow; the
        // traction is the face's whole (contactReporter shows that)
        history_.pressure() =
            master()
          ? scalarField(-(t & patch().nf()))
          : settings_.selfContact()
          ? ps
          : scalarField(t & corrector_.pair().normal());
    }

    // The face values follow from the cells and the gradient (before the
    // first contact update: the gradient read or initialised)
    Field<vector>::operator=
    (
        patchInternalField() + gradient()/patch().deltaCoeffs()
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidContactFvPatchVectorField::solidContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    contactLduInterfaceHolder(p),
    fixedGradientFvPatchVectorField(p, iF),
    lduInterfaceField(contactInterface_),
    history_(p)
{}


Foam::solidContactFvPatchVectorField::solidContactFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    contactLduInterfaceHolder(p),
    fixedGradientFvPatchVectorField(p, iF),
    lduInterfaceField(contactInterface_),
    settings_(p, dict, typeName),
    history_(p, dict, !settings_.master())
{
    if (dict.found("value"))
    {
        fvPatchVectorField::operator=(vectorField("value", dict, p.size()));
    }
    else
    {
        fvPatchVectorField::operator=(patchInternalField());
    }

    // A restart continues from the written gradient, so that the face
    // stress of its first corrector is the one the run was written with
    gradient() =
        dict.found("gradient")
      ? vectorField("gradient", dict, p.size())
      : vectorField(p.size(), Zero);
}


Foam::solidContactFvPatchVectorField::solidContactFvPatchVectorField
(
    const solidContactFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    contactLduInterfaceHolder(p),
    fixedGradientFvPatchVectorField(ptf, p, iF, mapper),
    lduInterfaceField(contactInterface_),
    settings_(ptf.settings_),
    history_(ptf.history_, p, ptf.settings_.dict(), mapper)
{}


Foam::solidContactFvPatchVectorField::solidContactFvPatchVectorField
(
    const solidContactFvPatchVectorField& ptf
)
:
    solidContactFvPatchVectorField(ptf, ptf.internalField())
{}


Foam::solidContactFvPatchVectorField::solidContactFvPatchVectorField
(
    const solidContactFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    contactLduInterfaceHolder(ptf.patch()),
    fixedGradientFvPatchVectorField(ptf, iF),
    lduInterfaceField(contactInterface_),
    settings_(ptf.settings_),
    history_(ptf.history_, ptf.patch(), ptf.settings_.dict()),
    corrector_(ptf.corrector_),
    gradInternal_(ptf.gradInternal_),
    gradBoundary_(ptf.gradBoundary_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidContactFvPatchVectorField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    // The mesh lists the interface of every contact patch, a rigid tool's
    // too: the matrix lists every lduInterfaceField, and GAMG needs the
    // mesh's interface where the field has one (a rigid tool's adds no
    // neighbours, updateInterfaceMatrix)
    registerInterface(internalField().name());

    if (master())
    {
        // The slave first, so that the coupling is this corrector's
        solidContactFvPatchVectorField& slave =
            const_cast<solidContactFvPatchVectorField&>(shadow());
        slave.updateCoeffs();

        history_.explicitTraction() =
            solidPatchTractions::explicitNormalTraction(patch());

        if (coupling())
        {
            setCoefficients
            (
                assemblyForce(primitiveField()),
                coupling()->masterDiag()
            );
        }
        else
        {
            // Before the slave's first update: the written force (zero at
            // a fresh start)
            setCoefficients
            (
                history_.traction()*patch().magSf(),
                vectorField(patch().size(), Zero)
            );
        }
        reporter().writeFields();
    }
    else
    {
        corrector_.correct(*this, shadowPtr(), settings_, history_);
        const contactInterfaceCoupling& c = corrector_.coupling();
        setCoefficients
        (
            assemblyForce(primitiveField()),
            settings_.selfContact()
          ? vectorField(c.slaveDiag() + c.masterDiag())
          : vectorField(c.slaveDiag())
        );
        corrector_.finish(patch(), history_);
    }

    fixedGradientFvPatchVectorField::updateCoeffs();
}


void Foam::solidContactFvPatchVectorField::evaluate
(
    const Pstream::commsTypes commsType
)
{
    if (!updated())
    {
        updateCoeffs();
    }

    // The tractions and face values of the solve just made, from its cell
    // values: the face values then agree with what the matrix held.
    // updateFromCells sets the values, so fixedGradient's evaluate (which
    // would set them again) is skipped
    updateFromCells();

    fvPatchVectorField::evaluate(commsType);
}


Foam::tmp<Foam::Field<Foam::vector>>
Foam::solidContactFvPatchVectorField::gradientInternalCoeffs() const
{
    if (gradInternal_.size() != size())
    {
        return fixedGradientFvPatchVectorField::gradientInternalCoeffs();
    }
    return tmp<Field<vector>>(new Field<vector>(gradInternal_));
}


Foam::tmp<Foam::Field<Foam::vector>>
Foam::solidContactFvPatchVectorField::gradientBoundaryCoeffs() const
{
    if (gradBoundary_.size() != size())
    {
        return fixedGradientFvPatchVectorField::gradientBoundaryCoeffs();
    }
    return tmp<Field<vector>>(new Field<vector>(gradBoundary_));
}


void Foam::solidContactFvPatchVectorField::saveCorrectorState()
{
    history_.saveCorrector();
    savedValue_ = *this;
    savedGradient_ = gradient();
    savedGradInternal_ = gradInternal_;
    savedGradBoundary_ = gradBoundary_;
}


void Foam::solidContactFvPatchVectorField::restoreCorrectorState
(
    const bool frozen
)
{
    history_.restoreCorrector(frozen);
    if (savedValue_.size() == size())
    {
        vectorField::operator=(savedValue_);
        gradient() = savedGradient_;
        gradInternal_ = savedGradInternal_;
        gradBoundary_ = savedGradBoundary_;
    }
}


Foam::scalarField* Foam::solidContactFvPatchVectorField::acceleratedState
(
    scalarField& scale
)
{
    if (master())
    {
        return nullptr;
    }
    scalarField* lambda = history_.method().correctorMultipliers();
    if (lambda)
    {
        // K/h of each slave cell [Pa/m]: a multiplier over it is the
        // displacement that would carry it
        const fvMesh& mesh = patch().boundaryMesh().mesh();
        scale =
            solidPatchTractions::impK(patch())*patch().magSf()
           /scalarField(mesh.V().field(), patch().faceCells());
    }
    return lambda;
}


void Foam::solidContactFvPatchVectorField::updateInterfaceMatrix
(
    solveScalarField& result,
    const bool add,
    const solveScalarField& psiInternal,
    const scalarField&,
    const direction cmpt,
    const Pstream::commsTypes
) const
{
    // Against a rigid tool there are no neighbours: the patch's own
    // coefficients (setCoefficients) are all of the coupling
    if (settings_.rigid())
    {
        return;
    }

    // The matrix's own coefficients for this patch are the explicit source
    // (see setCoefficients); the coupling's are used instead
    addNeighbours
    (
        result, add, psiInternal, cmpt, patch().faceCells(),
        patch().boundaryMesh()[shadowPatchIndex()].faceCells()
    );
}


Foam::label Foam::solidContactFvPatchVectorField::shadowPatchIndex() const
{
    return patch().boundaryMesh().findPatchID(shadowPatchName());
}


void Foam::solidContactFvPatchVectorField::addNeighbours
(
    solveScalarField& result,
    const bool add,
    const UList<solveScalar>& psi,
    const direction cmpt,
    const labelUList& ownCells,
    const labelUList& partnerCells
) const
{
    const contactInterfaceCoupling* c = coupling();
    if (!c)
    {
        return;
    }

    // Self-contact: the patch is both, its faces the partners' too
    const scalarField nb
    (
        settings_.selfContact()
      ? scalarField
        (
            c->slaveNeighbour(psi, cmpt, partnerCells)
          + c->masterNeighbour(psi, cmpt, partnerCells)
        )
      : master()
      ? scalarField(c->masterNeighbour(psi, cmpt, partnerCells))
      : scalarField(c->slaveNeighbour(psi, cmpt, partnerCells))
    );

    // The neighbours enter the matrix product with the sign of an internal
    // face's off-diagonal coefficient
    const scalar sign = add ? 1 : -1;
    forAll(ownCells, facei)
    {
        result[ownCells[facei]] += sign*nb[facei];
    }
}


void Foam::solidContactFvPatchVectorField::autoMap
(
    const fvPatchFieldMapper& m
)
{
    fixedGradientFvPatchVectorField::autoMap(m);
    history_.autoMap(m);
    corrector_.clearGeometry();
}


void Foam::solidContactFvPatchVectorField::rmap
(
    const fvPatchVectorField& ptf,
    const labelList& addr
)
{
    fixedGradientFvPatchVectorField::rmap(ptf, addr);
    history_.rmap
    (
        refCast<const solidContactFvPatchVectorField>(ptf).history_,
        addr
    );
}


void Foam::solidContactFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    if (settings_.rigid())
    {
        // The tool's own write carries a force-controlled position
        if (tool())
        {
            tool()->write(os);
        }
        else
        {
            os.beginBlock("rigidSurface");
            settings_.rigidSurfaceDict().write(os, false);
            os.endBlock();
        }
    }
    else
    {
        os.writeEntry("shadowPatch", shadowPatchName());
        os.writeEntry("master", Switch(master()));
    }
    if (!master())
    {
        os.writeEntry("method", history_.method().methodName());
        history_.method().write(os);
        os.writeEntry("friction", history_.friction().frictionName());
        history_.friction().write(os);
        settings_.writeSlave(os);
    }
    history_.write(os);
    gradient().writeEntry("gradient", os);
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * Build Macros  * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchVectorField,
        solidContactFvPatchVectorField
    );
}
