(** The scratch space of the intersection routines, one per render worker: what a shape test
    leaves behind besides its depth (the part hit, the CSG member hit, what a julia fractal, a
    bicubic patch or a parametric surface found at the crossing), room for the crossings
    of one shape, the hits of a CSG's members, a mesh's traversal and a torus's quartic, and what
    a worker keeps of the shapes it meets (the isosurfaces' state, the smooth height fields'
    vertex normals), which the compiled scene does not hold because it is never written. Named
    fields, stored flat where they are floats, so that the hot path allocates nothing. *)

type slab = { mutable t_near : float; mutable t_far : float }
(** A box's slab crossings along the ray: where it enters and where it leaves (§15.1). *)

type growable = { mutable room : float array }
(** A float array that is replaced by a bigger one when a ray crosses more surfaces. *)

val big_floats : int -> float array
(** [big_floats n] is a fresh array of [n] zeros whose memory is asked of the system as it is
    needed. While the renderer runs, its collector keeps a margin of 100 times the live heap
    ([Render]), so that the heap grows by 101 times any block allocated then: 9.7 GB for the
    96 MB of a fractal's 3,000,000 iterations. For arrays that may be big. *)

type blob_room = {
  mutable bounds : float array;  (** a blob's interval list: where each component starts or stops … *)
  mutable marks : int array;  (** … and which: the element's index times 2, plus 1 where it stops *)
  mutable fcoeffs : float array;  (** each element's quartic along the ray, 5 floats each *)
  mutable queue : int array;  (** the nodes of its hierarchy waiting to be visited *)
  mutable found : float array;  (** the depths found *)
  acc : float array;  (** the sum of the active elements' quartics (5 floats), then room for 2 *)
}
(** The room of a blob's intersection (shape/blob.cpp), grown to its number of elements. *)

type iso_search = {
  mutable px : float;
  mutable py : float;
  mutable pz : float;  (** the ray searched, in the isosurface's space: its origin … *)
  mutable dx : float;
  mutable dy : float;
  mutable dz : float;  (** … and its direction, not renormalised *)
  mutable inv3 : float;  (** 1 or −1: the sign the function is searched with (ISO_ThreadData.Inv3) *)
  mutable maxg : float;  (** the max_gradient of this search, which [evaluate] changes *)
  mutable fmax : float;  (** the least value the search met *)
  mutable tl : float;  (** the root found *)
  mutable vlength : float;  (** the length of the direction *)
  mutable bx : float;
  mutable by : float;
  mutable bz : float;  (** where the last segment without a root began … *)
  mutable ex : float;
  mutable ey : float;
  mutable ez : float;  (** … and ended *)
  mutable frame : float array;  (** the frame the search evaluates the function in ({!iso_own.frame}) *)
}
(** An isosurface's root search in progress, and what the last one without a root leaves for
    the cache (POV-Ray's ISO_ThreadData). *)

type iso_own = {
  frame : float array;  (** the frame the root search evaluates the isosurface's function in *)
  mutable grad_used : float;
      (** max_gradient as [evaluate] raises it from search to search (POV-Ray writes it into the
          object); the parsed value until then *)
}
(** What a worker keeps for one isosurface of the scene, made when it first searches it. *)

type iso_room = {
  mutable cached : bool;  (** the last root search found none, and was not a shadow ray's *)
  mutable owner : int;
      (** the isosurface that search was for, by its number in the scene
          ({!Isosurface.compiled.slot}) *)
  at : iso_search;
  mutable own : iso_own option array;  (** by isosurface number: what the worker keeps for each it has searched *)
}
(** The state POV-Ray's isosurfaces keep per render thread: it carries from ray to ray, and a
    root search may answer from it (shape/isosurf.cpp). *)

type f32s = (float, Bigarray.float32_elt, Bigarray.c_layout) Bigarray.Array1.t

type vertex_normals = { mutable fields : (f32s * f32s) list }
(** The vertex normals of the smooth height fields a worker has shaded, each paired with the
    field's heights (its own array, by which the field is known): 3 per vertex, as POV-Ray stores
    them, each vertex's made when a normal first needs it (NaN until then) ({!Hfield.normal}). A
    cache that changes no result. *)

type t = {
  stats : Stats.t;  (** the worker's counters *)
  lim : Limits.t;  (** the depths shapes accept (POV-Ray's, or the robust mode's) *)
  robust : bool;  (** the robust mode: tolerances that do not depend on the scene's scale *)
  mesh_stack : float array;  (** traversal room of a mesh's hierarchy *)
  mesh_depth : float array;  (** the depth a mesh search found (one float) *)
  mutable part : int;
      (** the part of the shape the last depth was found on: a mesh face, a box side (1–6), a
          cylinder's or cone's base, cap or side (1, 2, 3), a text letter's face or wall *)
  mutable leaf : int;  (** the id of the member a CSG's nearest hit is on *)
  slab : slab;  (** a box's crossings … *)
  mutable side_near : int;  (** … the side entered (0: none) … *)
  mutable side_far : int;  (** … and the side left *)
  crossings : float array;
      (** one cylinder's, cone's or disc's crossings as (depth, part) pairs; a torus's, polygon's or
          quadric's plain depths *)
  glyph_crossings : growable;  (** one text letter's crossings as (depth, part) pairs *)
  hits : growable;  (** the hits of a CSG's members, [hit_width] floats each *)
  coeffs : float array;  (** a torus's quartic … *)
  roots : float array;  (** … its roots … *)
  depths : float array;  (** … and their world depths, unfiltered *)
  quartic : Polysolv.work;  (** the polynomial solver's room *)
  blob : blob_room;  (** a blob's intervals, quartics and depths *)
  curve : growable;  (** a prism's, lathe's or sor's crossings as (depth, part) pairs *)
  sextic : Polysolv.work;  (** the degree-6 solver's room (a cubic lathe) *)
  bcyl : growable;  (** a lathe's or sor's bounding-cylinder crossings ([Bcyl]) *)
  sextic_coeffs : float array;  (** a lathe segment's polynomial (7 coefficients) … *)
  sextic_roots : float array;  (** … and its roots (6) *)
  lathe_quadratic : float array;  (** a lathe's ray-parallel quadratic (3) … *)
  lathe_quadratic_roots : float array;  (** … and its roots (2) *)
  fractal_stack : growable;
      (** a julia fractal's iteration stack, 4 floats (x, y, z, w) per iteration; like POV-Ray's
          per-thread stack it keeps what deeper iterations left beyond the last one *)
  crossing : Crossing.t;
      (** what a julia fractal, a bicubic patch or a parametric surface found at the crossing its
          last [depth] test returned (written by every such test that finds one), or a CSG at the
          member hit it returned, when [reported] *)
  mutable reported : bool;
      (** the last [depth] test left its crossing's report in [crossing]; a nearest search clears
          it before each test, so that it tells the reporting shapes from the others *)
  reports : growable;
      (** the reports of the hits in [hits] that have one, {!Crossing.width} floats each, in the
          order they were pushed ({!push_reported}) *)
  mutable report_count : int;
      (** how many reports [reports] holds; a CSG's search starts it at 0 ([Csg.depth]) *)
  poly_room : float array;  (** a poly's powers of the ray, its polynomial in t, roots and depths *)
  iso : iso_room;
      (** the isosurfaces' per-thread state: the cache, which may carry from block to block, and
          what the worker keeps for each isosurface, which always does *)
  iso_hits : float array;  (** one isosurface's crossings as (depth, side) pairs, 11 at most *)
  mutable shadow_ray : bool;
      (** the ray the shapes are asked about is a shadow ray (POV-Ray's Ray::IsShadowTestRay),
          as each query of the tracer's nearest search tells them: an isosurface does not leave
          its misses in the cache for it *)
  vertex_normals : vertex_normals;  (** the smooth height fields' vertex normals made so far *)
}

val create : robust:bool -> Stats.t -> t
(** [create ~robust stats] is fresh scratch for one worker counting into [stats], with POV-Ray's
    depth limits or, when [robust], the robust mode's, and the isosurfaces' state of a thread
    that has searched nothing yet. *)

val renew : t -> Stats.t -> t
(** [renew w stats] is scratch for the worker's next block (or the parser's next trace()),
    counting into [stats]: it shares [w]'s rooms (grown as the earlier blocks needed, and always
    written before they are read), its caches and its isosurfaces' state, and starts as {!create}
    does (no part or leaf found, no crossing reported, not a shadow test). [w] is not
    used afterwards. *)

val forget_iso_cache : t -> unit
(** [forget_iso_cache w] empties the isosurfaces' cache of [w], as a new thread's is, keeping
    what the worker keeps for each isosurface. *)

val forget_isosurfaces : t -> unit
(** [forget_isosurfaces w] is [w]'s isosurfaces' state as a new thread's, for a newly compiled
    scene whose isosurfaces are numbered anew: the cache and what was kept for each. *)

val hit_width : int
(** [hit_width] is the number of floats per hit in [hits]: depth, part, the member's id, the
    hit point's x, y, z, and the index of its report in [reports] (−1 for none). *)

val push_hit : t -> int -> float -> int -> int -> float -> float -> float -> int
(** [push_hit w n t part id px py pz] appends, after the first [n] hits of [w.hits], the hit of
    the member [id] at depth [t] on its [part] at the point (px, py, pz), without a report; it is
    [n + 1]. *)

val push_reported : t -> int -> float -> int -> int
(** [push_reported w n t id] appends, after the first [n] hits of [w.hits], the hit of the member
    [id] at depth [t] (no part) whose report is [w.crossing]: at its point, the report kept in
    [reports]; it is [n + 1]. *)

val hit_report : t -> int -> bool
(** [hit_report w j] is whether the [j]th hit of [w.hits] has a report, which it then puts in
    [w.crossing]. *)

val push_ray : t -> int -> float -> float -> int -> int -> Vec.t -> Vec.t -> int
(** [push_ray w n lo t part id o d] is [push_hit] of the point [o + t·d] when [t ≥ lo], else [n]. *)

val nearest_pair : t -> float array -> int -> float -> float
(** [nearest_pair w h n lo] is the nearest of the first [n] (depth, part) pairs of [h] at least
    [lo], its part left in [w.part]; or infinity. The pairs are read from the last, keeping a
    strictly nearer one, so of equal depths the last found wins (POV-Ray's intersection stack). *)

val nearest_crossing : t -> int -> float -> float
(** [nearest_crossing w n lo] is the nearest of the [n] (depth, part) pairs in [w.crossings] at
    least [lo], its part left in [w.part]; or infinity. POV-Ray takes them from the top of its
    intersection stack, keeping a strictly nearer one, so of equal depths the last found wins. *)

val nearest_depth : t -> int -> float -> float
(** [nearest_depth w n lo] is the nearest of the [n] plain depths in [w.crossings] at least [lo],
    or infinity; of equal depths the last found wins, as for [nearest_crossing]. *)
