// The extended method's detection: smooth regions segmented into separate
// surfaces, and a feature zone of any width between them whose vertices are
// labelled with the surface they belong to.
//
// The paper's filters find a chamfer only where it is one triangle wide and
// every vertex next to it is red. Marching cubes leaves bands two or more
// triangles wide and whole corner patches whose vertices are not red. Here the
// smooth part is split into regions (the paper's "global approach": triangles
// connected through smooth edges), thin corridors are returned to the zone,
// so are region contacts and internal creases (a region that leaked around
// the fading end of a feature), and each zone vertex takes the label of the
// nearby region whose local plane it lies closest to. An edge whose endpoints
// carry different labels, or one label with planes 45 degrees apart, crosses
// a sharp edge; a face with three labels contains a corner. The split and the
// placement then follow the paper, with planes fitted to each region near
// the feature instead of one vertex's normal.
//
// The stages live in extended/: segmentation.h (regions and what returns to
// the zone), plane_fit.h (a region's plane near a vertex), zone_labels.h
// (labels and the chamfer marks), projection.h (zone vertices onto their
// planes, after placement); zones.h holds the state they share.
#pragma once

#include "plane_fit.h"
#include "projection.h"
#include "segmentation.h"
#include "zone_labels.h"
#include "zones.h"
