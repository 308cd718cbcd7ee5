(** The quadric (POV-Ray's [shape/quadrics.cpp], [parse.cpp: Parse_Quadric]): the surface
    A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0, solid where the left side is
    at most 0. It lives in world space: a transform changes the coefficients, never the ray. POV-Ray's
    bounding box is a history (computed from the coefficients as read, then mapped by each transform),
    so it is carried in the record. *)

type t = {
  xx : float;
  yy : float;
  zz : float;  (** the square terms A, B, C (POV-Ray's Square_Terms) *)
  xy : float;
  xz : float;
  yz : float;  (** the mixed terms D, E, F (Mixed_Terms) *)
  lx : float;
  ly : float;
  lz : float;  (** the linear terms G, H, I (Terms) *)
  k : float;  (** the constant J *)
  box_llx : float;
  box_lly : float;
  box_llz : float;  (** POV-Ray's box: its lower corner … *)
  box_lenx : float;
  box_leny : float;
  box_lenz : float;  (** … and its lengths, each in single precision *)
}

val make : square:Vec.t -> mixed:Vec.t -> linear:Vec.t -> float -> t
(** [make ~square ~mixed ~linear j] is [quadric { square, mixed, linear, j }] with the box
    Parse_Quadric gives it ([box_within] the whole space, from the default huge box). *)

val transform : t -> Transform.t -> t
(** [transform q tr] is [q] moved by [tr] (Transform_Quadric: the 4×4 coefficient matrix Q becomes
    I·Q·Iᵀ with I the inverse of [tr], the mixed and linear terms the sums of the symmetric
    entries), its box mapped by [tr] (Recompute_BBox). *)

val invert : t -> t
(** [invert q] is [inverse] on a quadric: every coefficient negated (Quadric::Invert), so the
    solid is where the left side is at least 0, the surface included. The box stays. *)

val intersect : Stats.t -> Limits.t -> t -> Vec.t -> Vec.t -> float array -> int
(** [intersect stats lim q o d out] writes the depths of every crossing of the ray from [o] along
    the unit [d] into [out] (room for 2), in the order All_Intersections pushes them: the roots
    (−b + √Δ)/a then (−b − √Δ)/a, each kept when it is beyond [lim.near] and before [lim.far]
    (1e-6, 1e7); one root −c/2b when there is no square term along the ray. Returns how many.
    Counts the test, and its success when roots exist whatever their depth. Allocates nothing. *)

val normal : t -> Vec.t -> Vec.t
(** [normal q p] is the unit gradient of [q] at [p] (Quadric::Normal), <1,0,0> where it is zero. *)

val inside : t -> Vec.t -> bool
(** [inside q p] is Quadric::Inside: the left side at [p] is at most 0, the surface included. *)

val box_within : t -> float array -> float array -> float array
(** [box_within q lo hi] is POV-Ray's box of [q] confined to the box [lo]…[hi] (three corners'
    coordinates each), as Quadric::Compute_BBox(ClipMin, ClipMax) leaves it: from the normal forms it
    knows (ellipsoid, cylinders, cones, hyperboloids, paraboloids along an axis, translated), kept
    only when smaller than the box [q] had; lower corner and lengths, single precision. A CSG
    intersection bounds its quadric members this way within the others' box. *)

val bounds : t -> float array option
(** [bounds q] is POV-Ray's box of [q] as min x, y, z, max x, y, z; None when it is infinite ({!Pov_box.infinite}).
    POV-Ray culls rays by that box before it tries the quadric, so it may cut a sliver off the
    surface by its single-precision rounding, as it does there. *)

val bounds_within : t -> float array -> float array -> float array option
(** [bounds_within q lo hi] is [bounds] of the box [box_within q lo hi]. *)

val pov_box : t -> float array
(** [pov_box q] is POV-Ray's box of [q] (lower corner and lengths, single precision), [[||]] when
    it is infinite ({!Pov_box.infinite}). *)

val magnitude : t -> float
(** [magnitude q] is the size of the coordinates [q]'s intersection works with: its box's, or for
    an unbounded quadric the scale its coefficients give (a cylinder's radius, a paraboloid's
    focal length). *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w q o d lo] is the nearest root at least [lo], or infinity. *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w q id o d lo n] pushes the roots at least [lo], in the order found, as hits of the
    member [id] (Quadric::All_Intersections); it is the new count. *)

val traits : Traits.t
(** [traits] is its kind's traits: [inverse] negates its coefficients (and sets the flag), so its
    own Inside holds the inversion. *)
