(** Render statistics: rays by kind and intersection tests, counted by each render worker. *)

type t = {
  mutable camera_rays : int;
  mutable reflected_rays : int;
  mutable refracted_rays : int;  (** refracted, and transmitted at ior 1 *)
  mutable shadow_rays : int;
  mutable sphere_tests : int;
  mutable sphere_hits : int;
  mutable plane_tests : int;
  mutable plane_hits : int;
  mutable triangle_tests : int;
  mutable triangle_hits : int;
  mutable mesh_tests : int;
  mutable mesh_hits : int;
  mutable box_tests : int;
  mutable box_hits : int;
  mutable cone_tests : int;  (** cylinders and cones *)
  mutable cone_hits : int;
  mutable disc_tests : int;
  mutable disc_hits : int;
  mutable torus_tests : int;
  mutable torus_hits : int;  (** calls that found at least one root, whatever its depth (§15.5) *)
  mutable torus_bound_hits : int;  (** calls that passed the thick-cylinder pre-test *)
  mutable roots_tested : int;  (** quartics solved (POV-Ray's "Roots tested") *)
  mutable roots_eliminated : int;  (** of which a root at 0 was dropped (§15.6) *)
  mutable max_level : int;  (** deepest trace level reached *)
  mutable samples : int;  (** antialiasing samples beyond the first per pixel *)
  mutable csg_union_tests : int;  (** kept unions searched (§16.2) *)
  mutable csg_union_hits : int;
  mutable csg_intersection_tests : int;  (** intersections and differences searched *)
  mutable csg_intersection_hits : int;
  mutable csg_merge_tests : int;
  mutable csg_merge_hits : int;
  mutable ttf_tests : int;  (** text letters tested (§15.9) *)
  mutable ttf_hits : int;  (** tests that found a crossing beyond 1e-6 *)
  mutable polygon_tests : int;  (** polygons tested, degenerate ones not (§15.7) *)
  mutable polygon_hits : int;  (** tests whose crossing is within the depth limits and the outline *)
  mutable quadric_tests : int;  (** quadrics tested *)
  mutable quadric_hits : int;  (** tests that found a root pair or a linear root, whatever its depth *)
  mutable bound_tests : int;  (** bounding objects tested for a ray (Ray_In_Bound, one per object) *)
  mutable bound_hits : int;  (** of those, the ones the ray met or started inside *)
  mutable blob_tests : int;  (** blobs tested (shape/blob.cpp) *)
  mutable blob_hits : int;  (** tests that found a depth within the limits *)
  mutable blob_element_tests : int;  (** blob elements tested for their span along the ray *)
  mutable blob_element_hits : int;  (** of which the ray passed through the element's sphere of influence *)
  mutable blob_bound_tests : int;  (** nodes of a blob's hierarchy tested *)
  mutable blob_bound_hits : int;  (** of which the ray passed within the node's sphere *)
  mutable hfield_tests : int;  (** height fields tested *)
  mutable hfield_hits : int;  (** tests whose walk found a hit, whatever its depth *)
  mutable hfield_box_hits : int;  (** tests whose ray met the field's box (every test tries it) *)
  mutable hfield_triangle_tests : int;  (** triangles whose height range met the ray's *)
  mutable hfield_triangle_hits : int;  (** of which the ray crossed the triangle within the depths *)
  mutable hfield_block_tests : int;  (** blocks walked through *)
  mutable hfield_block_hits : int;  (** of which the ray's height met the block's *)
  mutable hfield_cell_tests : int;  (** cells walked through *)
  mutable hfield_cell_hits : int;  (** of which the ray's height met the cell's *)
  mutable superellipsoid_tests : int;  (** superellipsoids tested *)
  mutable superellipsoid_hits : int;  (** tests that kept a hit *)
  mutable ovus_tests : int;  (** ovus shapes tested *)
  mutable ovus_hits : int;  (** tests that kept a hit *)
  mutable sphere_sweep_tests : int;  (** sphere sweeps tested *)
  mutable sphere_sweep_hits : int;  (** tests that kept a hit beyond the sweep's tolerance *)
  mutable prism_tests : int;  (** prisms tested, degenerate ones not (prism.cpp) *)
  mutable prism_hits : int;  (** tests that pushed a crossing *)
  mutable prism_bound_tests : int;  (** its bounding tests (POV-Ray's "Bound" row) *)
  mutable prism_bound_hits : int;
  mutable lathe_tests : int;  (** lathes tested (lathe.cpp) *)
  mutable lathe_hits : int;  (** tests that pushed a crossing *)
  mutable lathe_bound_tests : int;  (** its bounding tests (POV-Ray's "Bound" row) *)
  mutable lathe_bound_hits : int;
  mutable sor_tests : int;  (** surfaces of revolution tested (sor.cpp) *)
  mutable sor_hits : int;  (** tests that pushed a crossing *)
  mutable sor_bound_tests : int;  (** its bounding tests (POV-Ray's "Bound" row) *)
  mutable sor_bound_hits : int;
  mutable fractal_tests : int;  (** julia fractals tested *)
  mutable fractal_hits : int;  (** tests whose march found a crossing, whatever its depth *)
  mutable bicubic_tests : int;  (** bicubic patches tested *)
  mutable bicubic_hits : int;  (** tests that found a crossing beyond 1e-5 *)
  mutable poly_tests : int;  (** polys, cubics and quartics tested *)
  mutable poly_hits : int;  (** tests that found a root, whatever its depth *)
  mutable parametric_tests : int;  (** parametric surfaces searched (their container met) *)
  mutable parametric_hits : int;  (** searches that found a crossing before the container's far side *)
  mutable parametric_bound_tests : int;  (** containers tested (POV-Ray's "Parametric Bound") *)
  mutable parametric_bound_hits : int;  (** of which the ray met the container *)
  mutable parametric_cut : int;  (** searches povml cut off at [Parametric.max_pieces] pieces *)
  mutable iso_tests : int;  (** isosurfaces searched: the ray crossed their container by at least the accuracy *)
  mutable iso_hits : int;  (** of which the search kept a crossing *)
  mutable iso_bound_tests : int;  (** isosurfaces tested (their container first: POV-Ray's "Isosurface Container") *)
  mutable iso_bound_hits : int;  (** of which the ray crossed the container *)
  mutable iso_cache_tests : int;  (** root searches that asked the cache of the last missed segment *)
  mutable iso_cache_hits : int;  (** of which the cache answered "no root" *)
  mutable iso_roots : int;  (** root searches (POV-Ray's "Isosurface roots") *)
  mutable iso_found : float array;
      (** what the searches found, [iso_width] floats per isosurface ({!iso_slot}): the largest
          gradient met (IsoSurface::gradient), then what [evaluate] found (ISO_Max_Gradient):
          the largest max_gradient it used, the searches that found a root, the sum of the
          max_gradient they ended with, the largest change of max_gradient in one search *)
}

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
(** One line of the "Ray->Shape Intersection" table: a shape's name as POV-Ray prints it, its
    tests and the tests that succeeded. Each shape module makes its own rows. *)
