/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactReport.H"
#include "MeshedSurfaces.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "solidContactFvPatchVectorField.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(contactReport, 0);
    addToRunTimeSelectionTable(functionObject, contactReport, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::contactReport::findSlaves()
{
    if (!mesh_.foundObject<volVectorField>(fieldName_))
    {
        FatalErrorInFunction
            << "Function object " << name() << ": no field " << fieldName_
            << " (entry 'field') in the registry" << exit(FatalError);
    }

    const volVectorField& D = mesh_.lookupObject<volVectorField>(fieldName_);

    DynamicList<label> slaves;
    wordList names;
    forAll(D.boundaryField(), patchi)
    {
        const fvPatchVectorField& pf = D.boundaryField()[patchi];
        if
        (
            isA<solidContactFvPatchVectorField>(pf)
         && !refCast<const solidContactFvPatchVectorField>(pf).master()
        )
        {
            slaves.append(patchi);
            names.append(pf.patch().name());
        }
    }
    slavePatches_.transfer(slaves);
    rigid_.setSize(slavePatches_.size());
    forAll(slavePatches_, i)
    {
        rigid_[i] =
            refCast<const solidContactFvPatchVectorField>
            (
                D.boundaryField()[slavePatches_[i]]
            ).rigid();
    }
    multiplierFiles_.setSize(slavePatches_.size());
    resetNames(names);

    // The column names (logFiles creates the files but leaves the header
    // to us), so that a reader is told what each column is and its units
    if (Pstream::master())
    {
        forAll(names, i)
        {
            writeFileHeader(i);
        }
    }
}


void Foam::functionObjects::contactReport::writeMultipliers(const label i)
{
    const volVectorField& D = mesh_.lookupObject<volVectorField>(fieldName_);
    const fvPatch& patch = D.boundaryField()[slavePatches_[i]].patch();
    const UList<solidContactFvPatchVectorField::multiplierRecord>& history =
        refCast<const solidContactFvPatchVectorField>
        (
            D.boundaryField()[slavePatches_[i]]
        ).multiplierHistory();

    if (!returnReduce(history.size(), maxOp<label>()))
    {
        return;
    }

    // This processor's rows (update, x, y, z, gap, pressure, multiplier) of
    // the faces whose multiplier was positive at some update
    const label nCol = 7;
    const vectorField& Cf = patch.Cf();
    DynamicList<scalar> rows;
    forAll(Cf, facei)
    {
        bool positive = false;
        for (const auto& rec : history)
        {
            positive = positive || rec.multiplier[facei] > 0;
        }
        if (!positive)
        {
            continue;
        }
        for (const auto& rec : history)
        {
            rows.append(rec.update);
            rows.append(Cf[facei].x());
            rows.append(Cf[facei].y());
            rows.append(Cf[facei].z());
            rows.append(rec.gap[facei]);
            rows.append(rec.pressure[facei]);
            rows.append(rec.multiplier[facei]);
        }
    }

    List<scalarList> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = rows;
    Pstream::gatherList(all);

    if (!Pstream::master())
    {
        return;
    }

    if (!multiplierFiles_.set(i))
    {
        multiplierFiles_.set(i, createFile(names()[i] + "Multipliers"));
        OFstream& os = multiplierFiles_[i];
        writeHeader
        (
            os,
            "Multiplier updates of slave patch " + names()[i]
          + ": per update the multipliers the inner correctors held and the"
            " gap and pressure they converged to"
        );
        writeCommented(os, "time");
        for
        (
            const char* col :
            {"update", "x", "y", "z", "gap", "pressure", "multiplier"}
        )
        {
            writeTabbed(os, col);
        }
        os  << endl;
    }

    OFstream& os = multiplierFiles_[i];
    for (const scalarList& procRows : all)
    {
        for (label r = 0; r + nCol <= procRows.size(); r += nCol)
        {
            writeCurrentTime(os);
            os  << tab << label(procRows[r]);
            for (label c = 1; c < nCol; ++c)
            {
                os  << tab << procRows[r + c];
            }
            os  << nl;
        }
    }
    os.flush();
}


void Foam::functionObjects::contactReport::writeTool(const label i) const
{
    const volVectorField& D = mesh_.lookupObject<volVectorField>(fieldName_);
    const solidContactFvPatchVectorField& pf =
        refCast<const solidContactFvPatchVectorField>
        (
            D.boundaryField()[slavePatches_[i]]
        );
    const rigidSurface* tool = pf.tool();
    if (!tool)
    {
        return;
    }

    // The tool's surface in its current position: a tessellation of an
    // analytic surface over twice the slave patch's extent (planes and
    // cylinders are infinite), a triangulated one as read. The box is
    // reduced over the processors, so every one of them gets here
    const boundBox bb(pf.patch().patch().localPoints(), true);
    if (!Pstream::master())
    {
        return;
    }
    pointField points;
    faceList faces;
    tool->tessellate(bb.centre(), bb.mag(), points, faces);
    const scalar t = mesh_.time().value();
    const c4f::rigid::RigidMotion m(tool->motion(t));
    forAll(points, k)
    {
        points[k] =
            c4fConvert::toFoam(m.apply(c4fConvert::toEigen(points[k])));
    }
    const fileName dir(baseFileDir()/name()/mesh_.time().timeName());
    mkDir(dir);
    meshedSurface(std::move(points), std::move(faces)).write
    (
        dir/(names()[i] + "_tool.vtk")
    );
}


void Foam::functionObjects::contactReport::writeFileHeader(const label i)
{
    OFstream& os = files(i);
    writeHeader(os, "Contact report of slave patch " + names()[i]);
    writeHeader
    (
        os,
        "Forces are totals over the patch as meshed [N]"
        " (per cell thickness in 2D)"
    );
    writeCommented(os, "time");
    for
    (
        const char* col :
        {
            "normalForce", "tangentialForce", "contactArea", "maxPressure",
            "maxPenetration", "activeFaces", "outerCorrectors", "converged",
            "multiplierUpdates", "minGap", "forceX", "forceY", "forceZ"
        }
    )
    {
        writeTabbed(os, col);
    }
    if (rigid_[i])
    {
        // The tool's translation [m] and the moment of the contact forces
        // on it about its current centre of rotation [N m]
        for
        (
            const char* col :
            {"toolX", "toolY", "toolZ", "toolMomentX", "toolMomentY",
             "toolMomentZ"}
        )
        {
            writeTabbed(os, col);
        }
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::contactReport::contactReport
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    logFiles(obr_, name),
    fieldName_("D"),
    slavePatches_()
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::contactReport::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    fieldName_ = dict.getOrDefault<word>("field", "D");
    return true;
}


bool Foam::functionObjects::contactReport::execute()
{
    return true;
}


bool Foam::functionObjects::contactReport::write()
{
    if (names().empty())
    {
        findSlaves();
    }

    const volVectorField& D = mesh_.lookupObject<volVectorField>(fieldName_);

    // Set by the solver after each load step
    const label converged =
        mesh_.data::lookupOrDefault<bool>("solidMechanicsConverged", false)
      ? 1 : 0;

    forAll(slavePatches_, i)
    {
        const solidContactFvPatchVectorField::report r =
            refCast<const solidContactFvPatchVectorField>
            (
                D.boundaryField()[slavePatches_[i]]
            ).contactReport();

        if (Pstream::master())
        {
            OFstream& os = files(i);
            writeCurrentTime(os);
            os  << tab << r.normalForce
                << tab << r.tangentialForce
                << tab << r.contactArea
                << tab << r.maxPressure
                << tab << r.maxPenetration
                << tab << r.activeFaces
                << tab << r.correctors
                << tab << converged
                << tab << r.multiplierUpdates
                << tab << r.minGap
                << tab << r.force.x()
                << tab << r.force.y()
                << tab << r.force.z();
            if (r.rigid)
            {
                os  << tab << r.toolTranslation.x()
                    << tab << r.toolTranslation.y()
                    << tab << r.toolTranslation.z()
                    << tab << r.toolMoment.x()
                    << tab << r.toolMoment.y()
                    << tab << r.toolMoment.z();
            }
            os  << endl;
        }

        writeMultipliers(i);

        if (rigid_[i])
        {
            writeTool(i);
        }
    }
    return true;
}
