(** Render statistics: rays by kind and every shape's intersection tests, counted by each render
    worker and added up over the workers. *)

type counts
(** Every counter's tests and hits, read and written through {!test}, {!hit}, {!tests} and
    {!hits}. *)

type t = {
  mutable camera_rays : int;
  mutable reflected_rays : int;
  mutable refracted_rays : int;  (** refracted, and transmitted at ior 1 *)
  mutable shadow_rays : int;
  mutable max_level : int;  (** deepest trace level reached *)
  mutable samples : int;  (** antialiasing samples beyond the first per pixel *)
  counts : counts;  (** the counters of the shapes and their solvers, by {!key} *)
  mutable iso_found : float array;
      (** what the searches found, [iso_width] floats per isosurface ({!iso_slot}): the largest
          gradient met (IsoSurface::gradient), then what [evaluate] found (ISO_Max_Gradient):
          the largest max_gradient it used, the searches that found a root, the sum of the
          max_gradient they ended with, the largest change of max_gradient in one search *)
}

type key
(** A counter: a number of tests and how many of them succeeded (hits), kept for one kind of
    shape (a shape with a pre-test or parts of its own has a counter for each). A new shape adds
    its key here and its row to the table. *)

val test : t -> key -> unit
(** [test s k] counts one more test of [k]. *)

val hit : t -> key -> unit
(** [hit s k] counts one more success of [k]. *)

val untest : t -> key -> unit
(** [untest s k] takes back one test counted as [k] that POV-Ray does not count as one. *)

val unhit : t -> key -> unit
(** [unhit s k] takes back one success counted as [k], likewise. *)

val tests : t -> key -> int
(** [tests s k] is the tests of [k] counted. *)

val hits : t -> key -> int
(** [hits s k] is the successes of [k] counted. *)

(** {2 The counters}

    The solvers', then those of POV-Ray's "Ray->Shape Intersection" table. *)

val roots : key
(** [roots]: polynomials solved (POV-Ray's "Roots tested"); hits: of which a root at 0 was dropped
    ("eliminated", §15.6). *)

val isosurface_roots : key
(** [isosurface_roots]: isosurface root searches (POV-Ray's "Isosurface roots"; no hits). *)

val parametric_cut : key
(** [parametric_cut]: parametric searches povml cut off at [Parametric.max_pieces] pieces (no
    hits). *)

val blob : key
(** [blob], the line "Blob": blobs tested (shape/blob.cpp); hits: tests that found a depth within
    the limits. *)

val blob_element : key
(** [blob_element], the line "Blob Component": blob elements tested for their span along the ray;
    hits: the ray passed through the element's sphere of influence. *)

val blob_bound : key
(** [blob_bound], the line "Blob Bound": nodes of a blob's hierarchy tested; hits: the ray passed
    within the node's sphere. *)

val bicubic : key
(** [bicubic], the line "Bicubic Patch": bicubic patches tested; hits: tests that found a crossing
    beyond 1e-5. *)

val box : key
(** [box], the line "Box": boxes tested; hits: tests that found a crossing within the limits. *)

val cone : key
(** [cone], the line "Cone/Cylinder": cylinders and cones tested; hits: tests that found a crossing.
    *)

val disc : key
(** [disc], the line "Disc": discs tested; hits: tests that found a crossing. *)

val csg_intersection : key
(** [csg_intersection], the line "CSG Intersection": intersections and differences searched; hits:
    searches that kept a hit. *)

val csg_merge : key
(** [csg_merge], the line "CSG Merge": merges searched; hits: searches that kept a hit. *)

val csg_union : key
(** [csg_union], the line "CSG Union": kept unions searched (§16.2); hits: searches that kept a
    hit. *)

val hfield : key
(** [hfield], the line "Height Field": height fields tested; hits: tests whose walk found a hit,
    whatever its depth. *)

val hfield_box : key
(** [hfield_box], the line "Height Field Box": height fields' boxes tested (every height field test
    tries it); hits: the ray met the box. *)

val hfield_triangle : key
(** [hfield_triangle], the line "Height Field Triangle": triangles whose height range met the ray's;
    hits: the ray crossed the triangle within the depths. *)

val hfield_block : key
(** [hfield_block], the line "Height Field Block": blocks walked through; hits: the ray's height met
    the block's. *)

val hfield_cell : key
(** [hfield_cell], the line "Height Field Cell": cells walked through; hits: the ray's height met
    the cell's. *)

val isosurface : key
(** [isosurface], the line "Isosurface": isosurfaces searched: the ray crossed their container by at
    least the accuracy; hits: the search kept a crossing. *)

val isosurface_container : key
(** [isosurface_container], the line "Isosurface Container": isosurfaces tested, their container
    first; hits: the ray crossed the container. *)

val isosurface_cache : key
(** [isosurface_cache], the line "Isosurface Cache": root searches that asked the cache of the last
    missed segment; hits: the cache answered "no root". *)

val lathe : key
(** [lathe], the line "Lathe": lathes tested (lathe.cpp); hits: tests that pushed a crossing. *)

val lathe_bound : key
(** [lathe_bound], the line "Lathe Bound": a lathe's bounding tests; hits: those passed. *)

val fractal : key
(** [fractal], the line "Fractal": julia fractals tested; hits: tests whose march found a crossing,
    whatever its depth. *)

val plane : key
(** [plane], the line "Plane": planes tested; hits: tests that found a crossing within the limits.
    *)

val polygon : key
(** [polygon], the line "Polygon": polygons tested, degenerate ones not (§15.7); hits: the crossing
    is within the depth limits and the outline. *)

val prism : key
(** [prism], the line "Prism": prisms tested, degenerate ones not (prism.cpp); hits: tests that
    pushed a crossing. *)

val prism_bound : key
(** [prism_bound], the line "Prism Bound": a prism's bounding tests; hits: those passed. *)

val parametric : key
(** [parametric], the line "Parametric": parametric surfaces searched (their container met); hits:
    searches that found a crossing before the container's far side. *)

val parametric_bound : key
(** [parametric_bound], the line "Parametric Bound": parametric surfaces' containers tested; hits:
    the ray met the container. *)

val quadric : key
(** [quadric], the line "Quadric": quadrics tested; hits: tests that found a root pair or a linear
    root, whatever its depth. *)

val poly : key
(** [poly], the line "Quartic/Poly": polys, cubics and quartics tested; hits: tests that found a
    root, whatever its depth. *)

val triangle : key
(** [triangle], the line "Triangle": triangles and smooth triangles tested; hits: tests that found a
    crossing. *)

val mesh : key
(** [mesh], the line "Mesh": meshes tested; hits: tests that found a crossing. *)

val ovus : key
(** [ovus], the line "Ovus": ovus shapes tested; hits: tests that kept a hit. *)

val sphere : key
(** [sphere], the line "Sphere": spheres and ellipsoids tested; hits: tests that found a crossing
    within the limits. *)

val sphere_sweep : key
(** [sphere_sweep], the line "Sphere Sweep": sphere sweeps tested; hits: tests that kept a hit
    beyond the sweep's tolerance. *)

val superellipsoid : key
(** [superellipsoid], the line "Superellipsoid": superellipsoids tested; hits: tests that kept a
    hit. *)

val sor : key
(** [sor], the line "Surface of Revolution": surfaces of revolution tested (sor.cpp); hits: tests
    that pushed a crossing. *)

val sor_bound : key
(** [sor_bound], the line "Surface of Rev. Bound": a sor's bounding tests; hits: those passed. *)

val torus : key
(** [torus], the line "Torus": tori tested; hits: tests that found at least one root, whatever its
    depth (§15.5). *)

val torus_bound : key
(** [torus_bound], the line "Torus Bound": tori's thick-cylinder pre-tests (one per torus test);
    hits: those passed. *)

val glyph : key
(** [glyph], the line "True Type Font": text letters tested (§15.9); hits: tests that found a
    crossing beyond 1e-6. *)

val bounding_object : key
(** [bounding_object], the line "Bounding Object": bounding objects tested for a ray (Ray_In_Bound,
    one per object); hits: the ray met it or started inside it. *)

val iso_width : int
(** [iso_width] is 5, the floats per isosurface in [iso_found]. *)

val iso_slot : t -> int -> int
(** [iso_slot s key] is where the values of the isosurface numbered [key] start in
    [s.iso_found], which it grows first if needed (new values are 0). *)

val create : unit -> t
(** [create ()] is a fresh record with every counter at 0. *)

val merge : t -> t -> t
(** [merge a b] is a new record with the counters of [a] and [b] added (max_level: the larger;
    in [iso_found] the counts and sums added, the others the larger). *)

type row = { name : string; tests : int; hits : int }
(** One line of the "Ray->Shape Intersection" table: a counter's name as POV-Ray prints it, its
    tests and the tests that succeeded. *)

val table : (string * key) list
(** [table] is the lines of POV-Ray's "Ray->Shape Intersection" table in the order it prints them
    (renderfrontend.cpp): each line's name and its counter. *)

val rows : t -> row list
(** [rows s] is every line of [table] with its counts in [s], those never tested included. *)
