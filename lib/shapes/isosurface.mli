(** The isosurface (POV-Ray's shape/isosurf.cpp): the points of its container where a user
    function of x, y, z equals the threshold, the function below it inside. A ray is searched
    by halving the part of it inside the container until the function, bounded by
    [max_gradient] times the distance, may change sign within an interval shorter than the
    accuracy (docs/isosurface.md). A search that finds no root leaves its segment in the
    worker's cache ({!Scratch.iso_room}), which may answer the next search of the same
    isosurface without evaluating the function: POV-Ray's images depend on it. *)

(** The container, in the isosurface's own space. *)
type container =
  | Box_container of { lo : Vec.t; hi : Vec.t }  (** corners sorted per axis *)
  | Sphere_container of { centre : Vec.t; radius : float }

(** [evaluate P0, P1, P2]: max_gradient adapted along each search (POV-Ray's eval_param). *)
type evaluate = { p0 : float; p1 : float; p2 : float }

type t = {
  fn : Fn.t;  (** the function of x, y, z *)
  container : container;  (** [contained_by], a box from −1 to 1 by default *)
  threshold : float;  (** 0 by default *)
  accuracy : float;  (** 0.001 by default; always positive *)
  max_gradient : float;  (** 1.1 by default; always positive *)
  max_trace : int;  (** the crossings searched per ray: 1 to 10 ([all_intersections]: 10) *)
  closed : bool;  (** no [open]: where the function is negative on the container's surface, it is surface *)
  evaluate : evaluate option;
  trans : Transform.t;  (** the isosurface's space to world: every modifier composed (identity at first) *)
  key : int;
      (** the number of the isosurface as parsed: its copies share it, as they share POV-Ray's
          ISO_Max_Gradient, and its statistics are kept under it ({!Stats.iso_slot}) *)
  copy : bool;  (** made from an identifier (IsoSurface::Copy): POV-Ray never warns about a copy *)
}

type compiled = {
  iso : t;
  slot : int;
      (** its number among the compiled scene's isosurfaces (0, 1, …, one for each object): it
          stands for the object (POV-Ray's [this]) in the worker's cache, and a worker keeps
          the function's frame and the max_gradient [evaluate] raises under it
          ({!Scratch.iso_room}) *)
  box : float array;  (** POV-Ray's box of it ({!pov_box}) *)
}
(** An isosurface ready to trace; immutable, what a search writes is the worker's. *)

val accuracy_default : float
(** 0.001. *)

val max_gradient_default : float
(** 1.1. *)

val max_trace_limit : int
(** 10, ISOSURFACE_MAXTRACE: the most crossings searched per ray. *)

val make : fn:Fn.t -> key:int -> t
(** [make ~fn ~key] is the isosurface of [fn] with POV-Ray's defaults. *)

val transform : t -> Transform.t -> t
(** [transform s m] is IsoSurface::Transform: [m] composed into its transform. *)

val mark_copy : t -> t
(** [mark_copy s] is [s] as IsoSurface::Copy leaves it: a copy. *)

val compile : slot:int -> t -> compiled
(** [compile ~slot s] is the isosurface ready to trace, numbered [slot] among the scene's. *)

val depth : Scratch.t -> compiled -> Vec.t -> Vec.t -> float -> float
(** [depth w c o d lo] is the nearest crossing at least [lo] of the ray from [o] along [d]
    (world space) that the search finds (every crossing it would push, as POV-Ray's
    Find_Intersection takes the nearest), its side left in [w.part]; or infinity. The search
    reads and updates the worker's state for [c] ({!Scratch.iso_room}). *)

val hits : Scratch.t -> compiled -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w c id o d lo n] pushes the crossings the search finds, at least [lo], as hits of the
    member [id] in POV-Ray's order (All_Intersections); it is the new count. *)

val normal : compiled -> int -> Vec.t -> Vec.t
(** [normal c side p] is IsoSurface::Normal at the world point [p]: a box container's side
    (1–6) has its axis, a point on a sphere container the sphere's normal, any other point the
    function's forward differences over the accuracy; by the inverse transpose, normalised. *)

val inside : compiled -> Vec.t -> bool
(** [inside c p] is whether [p] is in the container with the function at most the threshold
    there (IsoSurface::Inside, without the inverted flag). *)

val bounds : t -> float array
(** [bounds s] is the box of the container's box mapped by the transform. *)

val pov_box : t -> float array
(** [pov_box s] is IsoSurface::Compute_BBox: the container's box in single precision, then
    Recompute_BBox through the transform. *)

val warning : t -> Stats.t -> string option
(** [warning s stats] is the message POV-Ray gives at the end of the render about the
    max_gradient of a top-level isosurface that is not a copy (DispatchShutdownMessages), from
    what the render found ([stats.iso_found]): the gradient found against max_gradient, or what
    [evaluate] found; [None] when POV-Ray says nothing. *)

val traits : Traits.t
(** [traits] is its kind's traits: [Traits.default]. *)
