/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactSettings.H"
#include "emptyFvPatch.H"
#include "wedgeFvPatch.H"
#include "fvMesh.H"
#include "contactConstraintGroups.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::contactSettings::checkPatch
(
    const fvPatch& patch,
    const dictionary& dict
) const
{
    if (isA<emptyFvPatch>(patch) || isA<wedgeFvPatch>(patch))
    {
        FatalIOErrorInFunction(dict)
            << "Patch " << patch.name() << " of type " << patch.type()
            << " cannot carry the condition solidContact (" << dict.name()
            << "): contact needs a patch of type patch or wall"
            << exit(FatalIOError);
    }

    // On a 2D mesh the faces must lie across the solution plane: a face
    // whose normal has a part in the empty direction is not a contact
    // surface of the plane problem
    const fvMesh& mesh = patch.boundaryMesh().mesh();
    const Vector<label>& solD = mesh.solutionD();
    const vectorField n(patch.nf());
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (solD[d] == -1 && n.size() && max(mag(n.component(d))) > 1e-6)
        {
            FatalIOErrorInFunction(dict)
                << "Patch " << patch.name() << " (" << dict.name()
                << ") has faces whose normal points in the empty direction "
                << vector::componentNames[d] << " of this 2D mesh"
                << " (max |n_" << vector::componentNames[d] << "| = "
                << max(mag(n.component(d))) << "); a contact patch must"
                << " be normal to the solution plane" << exit(FatalIOError);
        }
    }

    if (normals_ != "faces" && normals_ != "smoothed" && normals_ != "nagata")
    {
        FatalIOErrorInFunction(dict)
            << "Invalid normals " << normals_ << " in " << dict.name()
            << ": valid are faces (the master face normal), smoothed"
            << " (interpolated point normals) and nagata (the gap and the"
            << " normal of a curved surface through the master points)"
            << exit(FatalIOError);
    }

    if (!contactConstraintGroups::sideNames.found(constraintFaces_))
    {
        FatalIOErrorInFunction(dict)
            << "Invalid constraintFaces " << constraintFaces_ << " in "
            << dict.name() << ": valid are "
            << contactConstraintGroups::sideNames.sortedToc()
            << " (slave: one constraint per slave face; master: one per"
            << " master face; auto: per master face where the slave is"
            << " much stiffer)" << exit(FatalIOError);
    }

    if (cellSize_ != "face" && cellSize_ != "patch")
    {
        FatalIOErrorInFunction(dict)
            << "Invalid cellSize " << cellSize_ << " in " << dict.name()
            << ": valid are face (h = V/A of each slave face's cell) and"
            << " patch (h = sum V / sum A over the slave patch)"
            << exit(FatalIOError);
    }

    if (!(rebuildTolerance_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Invalid rebuildTolerance " << rebuildTolerance_ << " in "
            << dict.name() << ": it must be a length >= 0 [m]"
            << " (0 rebuilds the search tree every corrector)"
            << exit(FatalIOError);
    }

    if (rigid_)
    {
        // No shadow to check; the tool's own entries are its class's
    }
    else if (self_ && master_)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'master yes' of " << dict.name() << ", whose"
            << " shadowPatch names the patch itself (self-contact): the"
            << " patch is both sides, its entry the slave's; remove"
            << " 'master' or set 'master no'" << exit(FatalIOError);
    }

    if (!rigid_ && patch.boundaryMesh().findPatchID(shadowPatchName_) < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'shadowPatch " << shadowPatchName_ << "' of "
            << dict.name() << ": there is no patch " << shadowPatchName_
            << nl << "Valid patches: " << patch.boundaryMesh().mesh().boundaryMesh().names()
            << exit(FatalIOError);
    }

    // -1 stands for "not given" inside; a given -1 is as invalid as -2
    if (dict.found("searchDistance") && !(searchDistance_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Invalid searchDistance " << searchDistance_ << " in "
            << dict.name() << ": it must be a positive length [m]"
            << exit(FatalIOError);
    }
}


void Foam::contactSettings::checkShadow
(
    const fvPatch& patch,
    const dictionary& dict,
    const word& typeName
) const
{
    // The boundaryField dictionary holds the shadow's entry when D was read
    // from a file; the field-level check in shadow() covers the rest
    if (dict.parent() == dictionary::null)
    {
        return;
    }
    const dictionary& bf = dict.parent();
    const dictionary* sdictPtr = bf.findDict(shadowPatchName_);
    if (!sdictPtr)
    {
        return;
    }
    const dictionary& sdict = *sdictPtr;

    const word shadowType(sdict.getOrDefault<word>("type", word::null));
    if (shadowType != typeName)
    {
        FatalIOErrorInFunction(sdict)
            << "The shadowPatch " << shadowPatchName_ << " of "
            << dict.name() << " has type '" << shadowType
            << "'; it must be " << typeName << " too, with shadowPatch "
            << patch.name() << exit(FatalIOError);
    }

    const word back(sdict.getOrDefault<word>("shadowPatch", word::null));
    if (back != patch.name())
    {
        FatalIOErrorInFunction(sdict)
            << "Entry 'shadowPatch " << back << "' of " << sdict.name()
            << " does not name " << patch.name() << ", whose shadowPatch"
            << " it is; the two patches must name each other"
            << exit(FatalIOError);
    }

    if (sdict.found("master"))
    {
        const bool shadowMaster = sdict.get<bool>("master");
        if (shadowMaster == master_)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'master " << (master_ ? "yes" : "no") << "' of "
                << dict.name() << " equals that of its shadowPatch "
                << shadowPatchName_ << "; exactly one patch of a pair is"
                << " the master: set 'master yes' on one and 'master no'"
                << " on the other" << exit(FatalIOError);
        }
    }
}


void Foam::contactSettings::checkRigid(const dictionary& dict) const
{
    if (!dict.isDict("rigidSurface"))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'rigidSurface' of " << dict.name() << " must be a"
            << " dictionary with the tool's type (plane, sphere, cylinder,"
            << " triSurface), its geometry and its motion"
            << exit(FatalIOError);
    }
    for (const word pairOnly : {"shadowPatch", "master"})
    {
        if (dict.found(pairOnly))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << pairOnly << "' of " << dict.name()
                << " beside 'rigidSurface': a patch touches either another"
                << " patch (shadowPatch and master) or a rigid tool"
                << " (rigidSurface); remove one" << exit(FatalIOError);
        }
    }
    if (dict.found("constraintFaces") && constraintFaces_ == "master")
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'constraintFaces master' of " << dict.name()
            << ": a rigid tool has no faces to pose the constraint on;"
            << " valid are slave and auto (both one constraint per slave"
            << " face here)" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactSettings::contactSettings()
:
    dict_(),
    rigid_(false),
    shadowPatchName_(),
    self_(false),
    master_(false),
    searchDistance_(-1),
    normals_("faces"),
    rebuildTolerance_(0),
    constraintFaces_("auto"),
    cellSize_("face")
{}


Foam::contactSettings::contactSettings
(
    const fvPatch& patch,
    const dictionary& dict,
    const word& typeName
)
:
    dict_(dict),
    rigid_(dict.found("rigidSurface")),
    shadowPatchName_
    (
        rigid_ ? word::null : dict.get<word>("shadowPatch")
    ),
    self_(!rigid_ && shadowPatchName_ == patch.name()),
    master_
    (
        rigid_ || self_
      ? dict.getOrDefault<bool>("master", false)
      : dict.get<bool>("master")
    ),
    searchDistance_(dict.getOrDefault<scalar>("searchDistance", -1)),
    normals_(dict.getOrDefault<word>("normals", "faces")),
    rebuildTolerance_(dict.getOrDefault<scalar>("rebuildTolerance", 0)),
    constraintFaces_(dict.getOrDefault<word>("constraintFaces", "auto")),
    cellSize_(dict.getOrDefault<word>("cellSize", "face"))
{
    // The relaxed target these entries controlled no longer exists: the
    // interface is implicit in the D matrix
    for (const word obsolete : {"couplingRelaxation", "aitken"})
    {
        if (dict.found(obsolete))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << obsolete << "' of " << dict.name()
                << " is no longer used: the contact interface is implicit"
                << " in the D matrix, with no relaxed target; remove it"
                << " (the outer correctors are accelerated in"
                << " solidMechanics of system/fvSolution)"
                << exit(FatalIOError);
        }
    }

    if (rigid_)
    {
        checkRigid(dict);
    }

    // The originals: a copied dictionary has no parent (the boundaryField
    // that holds the shadow's entry)
    checkPatch(patch, dict);
    if (!rigid_ && !self_)
    {
        checkShadow(patch, dict, typeName);
    }

    if (master_)
    {
        for (const word slaveOnly : {"method", "friction"})
        {
            if (dict.found(slaveOnly))
            {
                FatalIOErrorInFunction(dict)
                    << "Entry '" << slaveOnly << "' of " << dict.name()
                    << " on the master patch: the " << slaveOnly
                    << " is chosen on the slave patch (" << shadowPatchName_
                    << ", master no)" << exit(FatalIOError);
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactSettings::writeSlave(Ostream& os) const
{
    os.writeEntry("normals", normals_);
    os.writeEntry("rebuildTolerance", rebuildTolerance_);
    os.writeEntry("constraintFaces", constraintFaces_);
    os.writeEntry("cellSize", cellSize_);
    if (searchDistanceGiven())
    {
        os.writeEntry("searchDistance", searchDistance_);
    }
}


// ************************************************************************* //
