/*---------------------------------------------------------------------------*\
  contact4foam: computational contact mechanics for finite-volume solids
\*---------------------------------------------------------------------------*/

#include "contactPatchPair.H"
#include "polygonInterpolation.H"
#include "polygonOverlap.H"
#include "normalGap.H"
#include "eigenFoamConversions.H"
#include "Pstream.H"
#include "ListOps.H"
#include "mergePoints.H"
#include "boundBox.H"
#include "solidPatchTractions.H"
#include "syncTools.H"
#include "globalIndex.H"
#include "Map.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactPatchPair::contactPatchPair
(
    const fvPatch& slave,
    const fvPatch& master,
    const scalar searchDistance,
    const word& normals,
    const scalar rebuildTolerance
)
:
    slave_(slave),
    master_(master),
    self_(slave.index() == master.index()),
    searchDistance_(searchDistance),
    smoothNormals_(normals != "faces"),
    nagata_(normals == "nagata"),
    masterFaceSize_(0),
    surfaceGathered_(false),
    rebuildTolerance_(rebuildTolerance),
    staleness_(0),
    nBuilds_(0),
    hitFace_(slave.size(), -1),
    hitNormal_(slave.size(), Zero),
    hitLocal_(slave.size(), vector2D::zero),
    gap_(slave.size(), GREAT),
    inRange_(slave.size(), false)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::boundBox Foam::contactPatchPair::grownBox
(
    const UList<point>& x,
    const scalar r
)
{
    if (x.empty())
    {
        return boundBox();
    }
    const boundBox bb(x, false);
    return boundBox(bb.min() - vector::uniform(r), bb.max() + vector::uniform(r));
}


bool Foam::contactPatchPair::selectionStale
(
    const vectorField& masterD,
    const vectorField& slaveD
) const
{
    if (!masterMap_.valid())
    {
        return false;
    }
    // A slave face whose reach leaves the box, or a master face moved
    // by more than the margin (it may have come into another box)
    const vectorField x(slave_.Cf() + slaveD);
    const bool stale =
        (x.size() && !selectedBox_.contains(grownBox(x, reach())))
     || (masterD.size() && max(mag(masterD - selectedMasterD_)) > selectionMargin());
    return returnReduce(stale, orOp<bool>());
}


void Foam::contactPatchPair::gatherMasterSurface
(
    const vectorField& masterD,
    const vectorField& slaveD
)
{
    const polyPatch& pp = master_.patch();
    const pointField& lp = pp.localPoints();
    const faceList& lf = pp.localFaces();

    // Each face with its own reference points (merged again below)
    List<pointField> facePoints(lf.size());
    scalar h = 0;
    forAll(lf, facei)
    {
        facePoints[facei] = lf[facei].points(lp);
        h = max(h, boundBox(facePoints[facei], false).mag());
    }
    masterFaceSize_ = returnReduce(h, maxOp<scalar>());

    const labelList oldGlobal(masterGlobalFace_);
    labelList globalFace(identity(lf.size()));

    if (Pstream::parRun())
    {
        const globalIndex gi(lf.size());
        forAll(globalFace, facei)
        {
            globalFace[facei] = gi.toGlobal(facei);
        }

        // This processor's slave faces, where they are, and their reach
        selectedBox_ =
            grownBox(slave_.Cf() + slaveD, reach() + selectionMargin());
        List<boundBox> boxes(Pstream::nProcs());
        boxes[Pstream::myProcNo()] = selectedBox_;
        Pstream::gatherList(boxes);
        Pstream::scatterList(boxes);

        // Each local master face, where it is now, to every processor
        // whose box it meets
        List<boundBox> faceBoxes(lf.size());
        forAll(lf, facei)
        {
            faceBoxes[facei] =
                boundBox(facePoints[facei] + masterD[facei], false);
        }
        labelListList send(Pstream::nProcs());
        forAll(boxes, proci)
        {
            DynamicList<label> faces;
            if (boxes[proci].valid())
            {
                forAll(faceBoxes, facei)
                {
                    if (faceBoxes[facei].overlaps(boxes[proci]))
                    {
                        faces.append(facei);
                    }
                }
            }
            send[proci].transfer(faces);
        }
        masterMap_.reset(new mapDistributeBase(std::move(send)));
        masterMap_->distribute(facePoints);
        masterMap_->distribute(globalFace);
        selectedMasterD_ = masterD;

        Info<< "    contact " << slave_.name() << ": master faces held per"
            << " processor " << returnReduce(facePoints.size(), minOp<label>())
            << " .. " << returnReduce(facePoints.size(), maxOp<label>())
            << " of " << gi.size() << " (the reach of its slave faces, "
            << reach() + selectionMargin() << " m)" << endl;
    }
    masterGlobalFace_.transfer(globalFace);

    // Concatenate; merge the points faces share
    DynamicList<point> allPoints;
    faceList allFaces(facePoints.size());
    forAll(facePoints, facei)
    {
        face f(facePoints[facei].size());
        forAll(f, fp)
        {
            f[fp] = allPoints.size();
            allPoints.append(facePoints[facei][fp]);
        }
        allFaces[facei].transfer(f);
    }

    // The face each slave face saw at the step's start, in the new
    // numbering (-1 where it is no longer held)
    if (stepMasterFace_.size() && oldGlobal.size())
    {
        Map<label> index(2*masterGlobalFace_.size());
        forAll(masterGlobalFace_, facei)
        {
            index.insert(masterGlobalFace_[facei], facei);
        }
        for (label& j : stepMasterFace_)
        {
            j = (j >= 0 ? index.lookup(oldGlobal[j], -1) : -1);
        }
    }

    // The tolerance from the whole master's extent, the same on every
    // processor and in serial
    const boundBox bb(lp, true);
    labelList pointMap;
    mergePoints
    (
        pointField(allPoints),
        1e-9*max(bb.mag(), VSMALL),
        false,
        pointMap,
        masterRefPoints_
    );

    masterRefFaces_.transfer(allFaces);
    for (face& f : masterRefFaces_)
    {
        inplaceRenumber(pointMap, f);
    }
    masterRefCentres_.setSize(masterRefFaces_.size());
    forAll(masterRefFaces_, facei)
    {
        masterRefCentres_[facei] = masterRefFaces_[facei].centre(masterRefPoints_);
    }

    // Inverse-distance weights of the faces around each point
    List<DynamicList<label>> pf(masterRefPoints_.size());
    forAll(masterRefFaces_, facei)
    {
        for (const label pointi : masterRefFaces_[facei])
        {
            pf[pointi].append(facei);
        }
    }
    masterPointFaces_.setSize(pf.size());
    masterPointWeights_.setSize(pf.size());
    forAll(pf, pointi)
    {
        masterPointFaces_[pointi] = pf[pointi];
        scalarField& w = masterPointWeights_[pointi];
        w.setSize(pf[pointi].size());
        forAll(w, k)
        {
            const point c =
                masterRefFaces_[pf[pointi][k]].centre(masterRefPoints_);
            w[k] = 1/max(mag(c - masterRefPoints_[pointi]), VSMALL);
        }
        w /= sum(w);
    }

    masterFaces_.clear();
    for (const face& f : masterRefFaces_)
    {
        masterFaces_.push_back(std::vector<int>(f.begin(), f.end()));
    }

    if (self_)
    {
        setSelfExclusions();
    }
}


void Foam::contactPatchPair::setSelfExclusions()
{
    // The slave's points among the merged master points: merged again
    // with them, with the tolerance the master's were merged with
    const pointField& lp = slave_.patch().localPoints();
    const label nMaster = masterRefPoints_.size();
    pointField all(nMaster + lp.size());
    SubList<point>(all, nMaster) = masterRefPoints_;
    SubList<point>(all, lp.size(), nMaster) = lp;

    const boundBox bb(master_.patch().localPoints(), true);
    labelList pointMap;
    pointField merged;
    mergePoints(all, 1e-9*max(bb.mag(), VSMALL), false, pointMap, merged);

    labelList mergedToMaster(merged.size(), -1);
    for (label k = 0; k < nMaster; ++k)
    {
        mergedToMaster[pointMap[k]] = k;
    }

    const c4f::search::SelfContactFilter filter(masterFaces_);
    const faceList& lf = slave_.patch().localFaces();
    selfAround_.resize(lf.size());
    forAll(lf, facei)
    {
        std::vector<int> pts;
        for (const label p : lf[facei])
        {
            pts.push_back(int(mergedToMaster[pointMap[nMaster + p]]));
        }
        selfAround_[facei] = filter.facesAround(pts);
    }
}


void Foam::contactPatchPair::moveMaster(const vectorField& masterD)
{
    masterFaceD_ = gatherMaster(masterD);
    const vectorField& faceD = masterFaceD_;

    // Each face's value carried to the point with its cell's gradient, so
    // that a linear D moves the points exactly (see moveSlave)
    const tmp<tensorField> tgrad(cellGradients(master_));
    const vectorField Cf(gatherMaster(master_.Cf()));
    const vectorField nf(gatherMaster(master_.nf()()));
    const tensorField grad(gatherMaster(tgrad()));

    masterPoints_.resize(masterRefPoints_.size());
    forAll(masterRefPoints_, pointi)
    {
        vector d(Zero);
        const labelList& pf = masterPointFaces_[pointi];
        forAll(pf, k)
        {
            d +=
                masterPointWeights_[pointi][k]
               *(
                    faceD[pf[k]]
                  + tangential
                    (
                        nf[pf[k]],
                        (masterRefPoints_[pointi] - Cf[pf[k]]) & grad[pf[k]]
                    )
                );
        }
        masterPoints_[pointi] = c4fConvert::toEigen(masterRefPoints_[pointi] + d);
    }

    masterNormals_.resize(masterFaces_.size());
    std::vector<Eigen::Vector3d> areas(masterFaces_.size());
    forAll(masterRefFaces_, facei)
    {
        const std::vector<Eigen::Vector3d> poly(masterPolygon(facei));
        areas[facei] = c4f::transfer::areaVector(poly);
        masterNormals_[facei] = c4f::transfer::polygonPlane(poly).normal;
    }

    if (smoothNormals_)
    {
        masterPointNormals_.assign
        (
            masterPoints_.size(), Eigen::Vector3d::Zero()
        );
        forAll(masterPointFaces_, pointi)
        {
            Eigen::Vector3d n(Eigen::Vector3d::Zero());
            for (const label facei : masterPointFaces_[pointi])
            {
                n += areas[facei];
            }
            const double mag = n.norm();
            masterPointNormals_[pointi] = mag > 0 ? Eigen::Vector3d(n/mag) : n;
        }
    }

    if (nagata_)
    {
        masterPatches_.clear();
        masterPatches_.reserve(masterFaces_.size());
        std::vector<Eigen::Vector3d> pn;
        for (size_t facei = 0; facei < masterFaces_.size(); ++facei)
        {
            pn.clear();
            for (const int v : masterFaces_[facei])
            {
                pn.push_back(masterPointNormals_[v]);
            }
            masterPatches_.emplace_back(masterPolygon(facei), pn);
        }
    }
}


Eigen::Vector3d Foam::contactPatchPair::normalAt
(
    const label facei,
    const Eigen::Vector3d& x
) const
{
    if (!smoothNormals_)
    {
        return masterNormals_[facei];
    }

    if (nagata_ && masterPatches_[facei].valid())
    {
        const Eigen::Vector3d n(masterPatches_[facei].closest(x).normal);
        return n.norm() > 0 ? n : masterNormals_[facei];
    }

    // Mean value coordinates: on an edge they depend on its two points
    // alone, so the normal is continuous from one face to the next
    const std::vector<int>& f = masterFaces_[facei];
    const std::vector<double> w
    (
        c4f::transfer::meanValueCoordinates(masterPolygon(facei), x)
    );
    Eigen::Vector3d n(Eigen::Vector3d::Zero());
    for (size_t k = 0; k < f.size(); ++k)
    {
        n += w[k]*masterPointNormals_[f[k]];
    }
    const double mag = n.norm();
    return mag > 0 ? Eigen::Vector3d(n/mag) : masterNormals_[facei];
}


c4f::search::SearchHit Foam::contactPatchPair::closestCurved
(
    const Eigen::Vector3d& q,
    const c4f::search::SearchHit& flat,
    Eigen::Vector3d& normal
) const
{
    // A patch lies within half its diameter of its flat face (an edge's
    // coefficient is at most the edge long, a quad's interior within half
    // of the largest, a triangle's within a third), so the surface's
    // closest point is on a face within half the largest master face of
    // the flat hit's distance; the whole of the largest reference face
    // leaves room for faces stretched since
    const double reach = flat.distance + masterFaceSize_ + 2*staleness_;
    std::vector<int> cand
    (
        search_.facesInBox
        (
            q - Eigen::Vector3d::Constant(reach),
            q + Eigen::Vector3d::Constant(reach)
        )
    );
    if (std::find(cand.begin(), cand.end(), flat.face) == cand.end())
    {
        cand.push_back(flat.face);
    }

    // Nearest first by a lower bound of each patch's distance: that of
    // its points' box less the patch's bulge (NagataPatch::bulge(); a
    // flat polygon's is 0), so that the farther patches need no
    // projection. (Half the box's diagonal, the bound of before, is the
    // extrusion depth on a 2D mesh: every die face within it was
    // projected, 2.3 ms a corrector on shallowIroning.)
    std::vector<std::pair<double, int>> order;
    order.reserve(cand.size());
    for (const int j : cand)
    {
        const std::vector<int>& f = masterFaces_[j];
        Eigen::Vector3d lo(masterPoints_[f[0]]), hi(lo);
        for (const int v : f)
        {
            lo = lo.cwiseMin(masterPoints_[v]);
            hi = hi.cwiseMax(masterPoints_[v]);
        }
        const Eigen::Vector3d out
        (
            (lo - q).cwiseMax(q - hi).cwiseMax(0.0)
        );
        const c4f::search::NagataPatch& patch = masterPatches_[j];
        order.emplace_back
        (
            out.norm() - (patch.valid() ? patch.bulge() : 0.0),
            j
        );
    }
    std::sort(order.begin(), order.end());

    c4f::search::SearchHit best;
    bool bestInside = false;
    normal = masterNormals_[flat.face];
    const Eigen::Vector3d& nHit = masterNormals_[flat.face];
    const double tie = 1e-9*masterFaceSize_;
    for (const std::pair<double, int>& o : order)
    {
        const int j = o.second;
        if (best.found && o.first > best.distance + tie)
        {
            break;
        }
        if (masterNormals_[j].dot(nHit) <= 0)
        {
            // Only faces that face the way the hit face does
            continue;
        }

        c4f::search::NagataProjection proj;
        const c4f::search::NagataPatch& patch = masterPatches_[j];
        if (patch.valid())
        {
            proj = patch.closest(q);
        }
        else
        {
            // A polygon of more than four points is its flat face
            const c4f::search::SearchHit h(closestOnFaces({j}, q, GREAT));
            if (!h.found)
            {
                continue;
            }
            proj.point = h.point;
            proj.distance = h.distance;
            proj.normal = masterNormals_[j];
            proj.inside = true;
        }

        // The nearest point of the patches; of two at one point (an edge
        // the two patches share) the one inside its patch, whose normal
        // is that of the surface's closest point
        const bool better =
            !best.found
         || proj.distance < best.distance - tie
         || (
                proj.distance < best.distance + tie
             && proj.inside && !bestInside
            );
        if (better && proj.normal.norm() > 0)
        {
            best.found = true;
            best.face = j;
            best.point = proj.point;
            best.distance = proj.distance;
            bestInside = proj.inside;
            normal = proj.normal;
        }
    }
    if (!best.found)
    {
        return flat;
    }
    return best;
}


c4f::search::SearchHit Foam::contactPatchPair::closest
(
    const Eigen::Vector3d& q
) const
{
    if (staleness_ == 0)
    {
        return search_.closest(q, searchDistance_);
    }

    const c4f::search::SearchHit stale =
        search_.closest(q, searchDistance_ + staleness_);
    if (!stale.found)
    {
        return stale;
    }

    const double grow = stale.distance + 2*staleness_;
    const std::vector<int> cand
    (
        search_.facesInBox
        (
            q - Eigen::Vector3d::Constant(grow),
            q + Eigen::Vector3d::Constant(grow)
        )
    );

    return closestOnFaces(cand, q, searchDistance_);
}


std::vector<Eigen::Vector3d>
Foam::contactPatchPair::masterPolygon(const label facei) const
{
    std::vector<Eigen::Vector3d> poly;
    for (const int v : masterFaces_[facei])
    {
        poly.push_back(masterPoints_[v]);
    }
    return poly;
}


std::vector<Eigen::Vector3d>
Foam::contactPatchPair::slavePolygon(const label facei) const
{
    const face& f = slave_.patch().localFaces()[facei];
    std::vector<Eigen::Vector3d> poly;
    for (const label v : f)
    {
        poly.push_back(c4fConvert::toEigen(slavePoints_[v]));
    }
    return poly;
}


Foam::vector Foam::contactPatchPair::tangential
(
    const vector& n,
    const vector& v
)
{
    return v - n*(n & v);
}


Foam::tmp<Foam::tensorField> Foam::contactPatchPair::cellGradients
(
    const fvPatch& patch
)
{
    const fvMesh& mesh = patch.boundaryMesh().mesh();
    if (!mesh.foundObject<volTensorField>("gradD"))
    {
        return tmp<tensorField>(new tensorField(patch.size(), Zero));
    }
    return tmp<tensorField>
    (
        new tensorField
        (
            mesh.lookupObject<volTensorField>("gradD").primitiveField(),
            patch.faceCells()
        )
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactPatchPair::moveSlave(const vectorField& slaveD)
{
    const polyPatch& pp = slave_.patch();
    const polyMesh& mesh = pp.boundaryMesh().mesh();
    const labelListList& pointFaces = pp.pointFaces();
    const pointField& points = pp.localPoints();

    // A point on a processor boundary takes the faces of every processor
    // around it, so that a decomposed run sees the serial surface. The
    // weights are made by every processor together (syncPointList is
    // collective): the test on this processor's point count alone skipped
    // them where a processor holds no slave face, and the exchange then
    // mismatched (MPI_ERR_TRUNCATE)
    if
    (
        returnReduce(slavePointWeights_.size() != pp.nPoints(), orOp<bool>())
    )
    {
        slavePointWeights_.setSize(pp.nPoints());
        slavePointWeightSum_.setSize(pp.nPoints());
        const vectorField& Cf = slave_.Cf();
        forAll(pointFaces, pointi)
        {
            scalarList& w = slavePointWeights_[pointi];
            w.setSize(pointFaces[pointi].size());
            forAll(w, k)
            {
                w[k] =
                    1/max(mag(Cf[pointFaces[pointi][k]] - points[pointi]), VSMALL);
            }
            slavePointWeightSum_[pointi] = sum(w);
        }
        syncTools::syncPointList
        (
            mesh, pp.meshPoints(), slavePointWeightSum_, plusEqOp<scalar>(),
            scalar(0)
        );
    }

    // Each face's value is carried to the point with its cell's gradient,
    // in the face's plane: the weighted mean of the face values alone is
    // not exact for a linear D where the faces around a point are not
    // symmetric about it (a triangulated surface), and the overlaps, and
    // so the master's tractions, were then off by the lateral strain (the
    // tet patch test with nu = 0.3: 6.5e-4, 5e-7 with it). The normal
    // part is left to the mean: carried too, it made the tet sphere's
    // surface noisier (p_max +4.9 -> +6.0 % of Hertz, RMS 2.7 -> 3.3 %)
    const tmp<tensorField> tgrad(cellGradients(slave_));
    const tensorField& grad = tgrad();
    const vectorField& Cf = slave_.Cf();
    const vectorField nf(slave_.nf());
    vectorField d(pp.nPoints(), Zero);
    forAll(pointFaces, pointi)
    {
        forAll(pointFaces[pointi], k)
        {
            const label facei = pointFaces[pointi][k];
            d[pointi] +=
                slavePointWeights_[pointi][k]
               *(
                    slaveD[facei]
                  + tangential
                    (
                        nf[facei], (points[pointi] - Cf[facei]) & grad[facei]
                    )
                );
        }
    }
    syncTools::syncPointList
    (
        mesh, pp.meshPoints(), d, plusEqOp<vector>(), vector(Zero)
    );

    slavePoints_ = points + d/slavePointWeightSum_;
}


void Foam::contactPatchPair::update
(
    const vectorField& masterD,
    const vectorField& slaveD
)
{
    if
    (
        (
            !surfaceGathered_
         && returnReduce(master_.size(), sumOp<label>())
        )
     || selectionStale(masterD, slaveD)
    )
    {
        gatherMasterSurface(masterD, slaveD);
        surfaceGathered_ = true;
        builtPoints_.clear();
    }
    moveMaster(masterD);

    staleness_ = 0;
    if (builtPoints_.size() == masterPoints_.size())
    {
        for (size_t i = 0; i < masterPoints_.size(); ++i)
        {
            staleness_ =
                max(staleness_, (masterPoints_[i] - builtPoints_[i]).norm());
        }
    }
    if
    (
        builtPoints_.size() != masterPoints_.size()
     || staleness_ > rebuildTolerance_
    )
    {
        search_.build(masterPoints_, masterFaces_);
        builtPoints_ = masterPoints_;
        staleness_ = 0;
        ++nBuilds_;
    }

    moveSlave(slaveD);

    const vectorField x(slave_.Cf() + slaveD);

    forAll(x, facei)
    {
        const Eigen::Vector3d q(c4fConvert::toEigen(x[facei]));
        c4f::search::SearchHit hit;
        if (self_)
        {
            const Eigen::Vector3d ns
            (
                c4f::transfer::polygonPlane(slavePolygon(facei))
               .normal.normalized()
            );
            hit = closestSelf(q, facei, ns);

            // One pass: of two faces that face each other, one is the
            // slave, the other only its master
            if
            (
                hit.found
             && !c4f::search::SelfContactFilter::slaveOfPair
                (
                    ns, normalAt(hit.face, hit.point)
                )
            )
            {
                hit = c4f::search::SearchHit();
            }
        }
        else
        {
            hit = closest(q);
        }

        Eigen::Vector3d nCurved(Eigen::Vector3d::Zero());
        if (nagata_ && !self_ && hit.found)
        {
            hit = closestCurved(q, hit, nCurved);
        }

        inRange_[facei] = hit.found;
        if (hit.found)
        {
            hitFace_[facei] = hit.face;
            const Eigen::Vector3d n
            (
                nCurved.norm() > 0 ? nCurved : normalAt(hit.face, hit.point)
            );
            hitNormal_[facei] = c4fConvert::toFoam(n);
            gap_[facei] = (q - hit.point).dot(n);

            const std::vector<int>& f = masterFaces_[hit.face];
            Eigen::Vector3d c(Eigen::Vector3d::Zero());
            for (const int v : f)
            {
                c += masterPoints_[v];
            }
            c /= double(f.size());
            const Eigen::Vector3d t1
            (
                (masterPoints_[f[1]] - masterPoints_[f[0]]).normalized()
            );
            const Eigen::Vector3d t2(masterNormals_[hit.face].cross(t1));
            hitLocal_[facei] =
                vector2D((hit.point - c).dot(t1), (hit.point - c).dot(t2));
        }
        else
        {
            hitFace_[facei] = -1;
            hitNormal_[facei] = -slave_.nf()()[facei];
            gap_[facei] = searchDistance_;
        }
    }

    computeOverlaps(x);
}


void Foam::contactPatchPair::computeOverlaps(const vectorField& x)
{
    overlapFaces_.setSize(slave_.size());
    overlapWeights_.setSize(slave_.size());
    overlapGaps_.setSize(slave_.size());
    overlapCentroids_.setSize(slave_.size());
    slaveCentres_ = x;
    slaveNormals_ = slave_.nf();

    forAll(overlapFaces_, facei)
    {
        overlapFaces_[facei].clear();
        overlapWeights_[facei].clear();
        overlapGaps_[facei].clear();
        overlapCentroids_[facei].clear();
        if (!inRange_[facei])
        {
            continue;
        }

        const std::vector<Eigen::Vector3d> poly(slavePolygon(facei));

        // Each face's plane through its centre moved by its face value,
        // oriented as its current polygon
        const Eigen::Vector3d xs(c4fConvert::toEigen(x[facei]));
        const Eigen::Vector3d ns(c4f::transfer::polygonPlane(poly).normal);
        slaveNormals_[facei] =
            c4fConvert::toFoam(Eigen::Vector3d(ns.normalized()));
        const auto faceGap = [&](const label j, const Eigen::Vector3d& c)
        {
            const Eigen::Vector3d xm
            (
                c4fConvert::toEigen
                (
                    vector(masterRefCentres_[j] + masterFaceD_[j])
                )
            );
            if (nagata_ && masterPatches_[j].valid())
            {
                // The tangent plane of the face's patch at c, moved by
                // the face's own value less the points' (so that the
                // master's own face values stay in the gap, as below);
                // at a degenerate patch point (a collapsed edge, no
                // normal) the face's plane
                const c4f::search::NagataProjection proj
                (
                    masterPatches_[j].closest(c)
                );
                if (proj.normal.norm() > 0)
                {
                    return c4f::contact::planeGap
                    (
                        c,
                        proj.point + xm
                      - c4f::transfer::polygonCentroid(masterPolygon(j)),
                        proj.normal,
                        xs,
                        ns
                    );
                }
            }
            return c4f::contact::planeGap(c, xm, masterNormals_[j], xs, ns);
        };

        // Candidates: master faces near the slave polygon, the box grown by
        // the gap so that an open or penetrated face still finds them, and
        // by half its size: the gap is that of the centre, and the master
        // faces next to the hit face may lie farther from the polygon (a
        // wavy master in the first correctors of a step, a curved one)
        Eigen::Vector3d lo(poly[0]), hi(poly[0]);
        for (const Eigen::Vector3d& p : poly)
        {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        const double grow =
            mag(gap_[facei]) + staleness_ + 0.05*(hi - lo).norm();
        lo.array() -= grow;
        hi.array() += grow;

        const std::vector<int> cand(search_.facesInBox(lo, hi));

        std::vector<double> overlaps;
        std::vector<Eigen::Vector3d> centroids;
        overlaps.reserve(cand.size());
        centroids.reserve(cand.size());
        for (const int j : cand)
        {
            // Only faces that face the slave: the far side of a thin
            // master body must not share the force
            const double facing =
                self_
             && c4f::search::SelfContactFilter::excluded
                (
                    selfAround_[facei], ns, j, masterNormals_[j]
                )
              ? -1
              : masterNormals_[j].dot(masterNormals_[hitFace_[facei]]);
            const c4f::transfer::Polygon overlap
            (
                facing > 0
              ? c4f::transfer::overlapPolygon(poly, masterPolygon(j))
              : c4f::transfer::Polygon()
            );
            overlaps.push_back(c4f::transfer::polygonArea(overlap));
            centroids.push_back(c4f::transfer::polygonCentroid(overlap));
        }

        const std::vector<double> w
        (
            c4f::transfer::conservativeWeights(overlaps)
        );

        DynamicList<label> faces;
        DynamicList<scalar> weights;
        DynamicList<scalar> gaps;
        DynamicList<vector> cents;
        if (w.empty())
        {
            // No overlap: the projection's own face takes it all
            faces.append(hitFace_[facei]);
            weights.append(1);
            gaps.append(faceGap(hitFace_[facei], xs));
            cents.append(x[facei]);
        }
        else
        {
            for (size_t k = 0; k < cand.size(); ++k)
            {
                if (w[k] > 0)
                {
                    faces.append(cand[k]);
                    weights.append(w[k]);
                    gaps.append(faceGap(cand[k], centroids[k]));
                    cents.append(c4fConvert::toFoam(centroids[k]));
                }
            }
        }
        overlapFaces_[facei].transfer(faces);
        overlapWeights_[facei].transfer(weights);
        overlapGaps_[facei].transfer(gaps);
        overlapCentroids_[facei].transfer(cents);
    }
}


c4f::search::SearchHit Foam::contactPatchPair::closestSelf
(
    const Eigen::Vector3d& q,
    const label i,
    const Eigen::Vector3d& ns
) const
{
    // The tree cannot leave faces out: its candidates near q, filtered and
    // projected onto one by one (a face's gap decides whether it is a
    // pair, c4f::search::SelfContactFilter)
    const double grow = searchDistance_ + 2*staleness_;
    const std::vector<int> cand
    (
        search_.facesInBox
        (
            q - Eigen::Vector3d::Constant(grow),
            q + Eigen::Vector3d::Constant(grow)
        )
    );

    c4f::search::SearchHit best;
    for (const int j : cand)
    {
        const Eigen::Vector3d& nm = masterNormals_[j];
        if (c4f::search::SelfContactFilter::excluded(selfAround_[i], ns, j, nm))
        {
            continue;
        }
        const c4f::search::SearchHit hit
        (
            closestOnFaces({j}, q, searchDistance_)
        );
        if
        (
            !hit.found
         || c4f::search::SelfContactFilter::behindUnfaced
            (
                ns, nm, (q - hit.point).dot(normalAt(j, hit.point))
            )
         || (best.found && hit.distance >= best.distance)
        )
        {
            continue;
        }
        best = hit;
    }
    return best;
}


c4f::search::SearchHit Foam::contactPatchPair::closestOnFaces
(
    const std::vector<int>& cand,
    const Eigen::Vector3d& q,
    const scalar maxDistance
) const
{
    // The candidates as a small surface of their own, current points
    std::vector<Eigen::Vector3d> pts;
    std::vector<std::vector<int>> faces(cand.size());
    for (std::size_t k = 0; k < cand.size(); ++k)
    {
        for (const int v : masterFaces_[cand[k]])
        {
            faces[k].push_back(int(pts.size()));
            pts.push_back(masterPoints_[v]);
        }
    }
    c4f::search::SearchHit hit
    (
        c4f::search::bruteForceClosest(pts, faces, q, maxDistance)
    );
    if (hit.found)
    {
        hit.face = cand[hit.face];
    }
    return hit;
}


Foam::labelList Foam::contactPatchPair::passedThrough
(
    scalarField& depth
) const
{
    DynamicList<label> faces;
    DynamicList<scalar> depths;
    if (stepMasterFace_.size() == inRange_.size())
    {
        forAll(inRange_, facei)
        {
            const label j = stepMasterFace_[facei];
            if (inRange_[facei] || j < 0)
            {
                continue;
            }
            const Eigen::Vector3d x(c4fConvert::toEigen(slaveCentres_[facei]));
            const std::vector<Eigen::Vector3d> poly(masterPolygon(j));
            const double d =
                (x - c4f::transfer::polygonCentroid(poly))
               .dot(masterNormals_[j]);
            if (d < 0 && c4f::transfer::projectsInside(x, poly))
            {
                faces.append(facei);
                depths.append(-d);
            }
        }
    }
    depth.transfer(depths);
    return labelList(std::move(faces));
}


Foam::List<Foam::List<Foam::vector>> Foam::contactPatchPair::overlapCorrections
(
    const tensorField& slaveGrad,
    const tensorField& masterGrad
) const
{
    // The overlap centroids are in the current configuration; the gradients
    // are of the reference mesh (dD/dX). Under finite deformation a current
    // offset dx is dX = F^-1 dx of the reference, F = I + grad(D)^T (in
    // small strain the difference is second order and is left out, so
    // that every small-strain answer stays as it was)
    const bool finite =
        solidPatchTractions::finiteDeformation(slave_.boundaryMesh().mesh());
    const auto reference = [finite](const vector& dx, const tensor& G)
    {
        return finite ? vector(inv(I + G.T()) & dx) : dx;
    };

    List<List<vector>> delta(overlapFaces_.size());
    forAll(overlapFaces_, i)
    {
        const labelList& faces = overlapFaces_[i];
        delta[i].setSize(faces.size());
        forAll(faces, k)
        {
            const label j = faces[k];
            const vector& c = overlapCentroids_[i][k];
            const vector xm(masterRefCentres_[j] + masterFaceD_[j]);
            delta[i][k] =
                (reference(c - xm, masterGrad[j]) & masterGrad[j])
              - (reference(c - slaveCentres_[i], slaveGrad[i]) & slaveGrad[i]);
        }
    }
    return delta;
}


Foam::tmp<Foam::vectorField> Foam::contactPatchPair::masterForce
(
    const vectorField& slaveForce
) const
{
    vectorField F(masterFaces_.size(), Zero);

    forAll(slaveForce, facei)
    {
        const labelList& faces = overlapFaces_[facei];
        const scalarList& w = overlapWeights_[facei];
        forAll(faces, k)
        {
            F[faces[k]] -= w[k]*slaveForce[facei];
        }
    }

    return masterSum(F);
}


Foam::tmp<Foam::vectorField> Foam::contactPatchPair::relativeDisplacement
(
    const vectorField& slaveD,
    List<List<vector>>& corrections
) const
{
    tmp<vectorField> trel(slaveD - slaveValuesGathered(masterFaceD_));
    vectorField& rel = trel.ref();

    const word gradName("gradD");
    const tensorField slaveGrad
    (
        slave_.lookupPatchField<volTensorField, tensor>(gradName)
       .patchInternalField()
    );
    const tensorField masterGrad
    (
        gatherMaster
        (
            master_.lookupPatchField<volTensorField, tensor>
            (
                gradName
            ).patchInternalField()()
        )
    );
    corrections = overlapCorrections(slaveGrad, masterGrad);
    forAll(corrections, i)
    {
        forAll(corrections[i], k)
        {
            rel[i] -= overlapWeights_[i][k]*corrections[i][k];
        }
    }
    return trel;
}


Foam::tmp<Foam::scalarField> Foam::contactPatchPair::masterStiffness() const
{
    const fvMesh& mesh = master_.boundaryMesh().mesh();
    const scalarField masterKh
    (
        solidPatchTractions::impK(master_)*master_.magSf()
       /scalarField(mesh.V().field(), master_.faceCells())
    );
    return slaveValues(masterKh);
}


Foam::tmp<Foam::tensorField>
Foam::contactPatchPair::masterCellStress() const
{
    return slaveValues
    (
        solidPatchTractions::cellFluxStress(master_)()
    );
}


void Foam::contactPatchPair::gatherMasterData
(
    scalarField& K,
    scalarField& delta,
    vectorField& C,
    vectorField& faceCorrection,
    scalarField& magSf
) const
{
    K = gatherMaster(solidPatchTractions::impK(master_)());
    delta = gatherMaster(scalarField(1.0/master_.deltaCoeffs()));
    C = gatherMaster(solidPatchTractions::explicitNormalTraction(master_)());
    faceCorrection =
        gatherMaster(solidPatchTractions::faceCorrection(master_)());
    magSf = gatherMaster(master_.magSf());
}


Foam::tmp<Foam::vectorField> Foam::contactPatchPair::masterCellValues
(
    const vectorField& D,
    const int tag
) const
{
    return gatherMaster(vectorField(D, master_.faceCells()), tag);
}


Foam::tmp<Foam::scalarField> Foam::contactPatchPair::masterCellValues
(
    const UList<solveScalar>& psi,
    const labelUList& masterCells,
    const int tag
) const
{
    scalarField local(masterCells.size());
    forAll(masterCells, facei)
    {
        local[facei] = psi[masterCells[facei]];
    }
    return gatherMaster(local, tag);
}
