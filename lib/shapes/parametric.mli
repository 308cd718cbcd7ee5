(** The parametric surface (POV-Ray's shape/fpmetric.cpp): the points (x(u, v), y(u, v),
    z(u, v)) of three user functions over a rectangle of (u, v), within a container box or sphere.
    A ray is intersected by subdividing the rectangle: each piece's x, y and z are bounded from
    its corners and [max_gradient], the ray's depth ranges through those three slabs must overlap,
    and a piece smaller than [accuracy] (in (u, v), or in the depth range) is a crossing at the
    near depth of its last slab. Only the nearest crossing is kept. The surface has no inside;
    its normal and its UV coordinates come from the (u, v) of the piece found. *)

type container =
  | Box_container of Box.t  (** [contained_by { box { … } }], the default [<-1,-1,-1>, <1,1,1>] *)
  | Sphere_container of { centre : Vec.t; radius : float }  (** [contained_by { sphere { … } }] *)

(** [precompute depth, x, y, z]: the bounds of the chosen functions over the pieces of the first
    [depth] − 1 levels of subdivision, by piece number (1 the whole rectangle, 2k and 2k + 1 the
    halves of piece k). *)
type precomputed = {
  levels : int;  (** the depth, 1 … 20: pieces 1 … 2^depth − 1 *)
  low : float array array;  (** for x, y and z: each piece's lower bound, [[||]] when not chosen *)
  high : float array array;  (** … and its upper bound *)
}

type t = {
  fx : Fn.t;
  fy : Fn.t;
  fz : Fn.t;  (** the three functions, of u and v (their x and y registers) *)
  umin : float;
  umax : float;
  vmin : float;
  vmax : float;  (** the rectangle, each pair sorted *)
  accuracy : float;  (** the smallest piece (0.001 by default), also the normal's step *)
  max_gradient : float;  (** the steepest a function is assumed to be (1 by default) *)
  container : container;
  trans : Transform.t;  (** parametric space to world: POV-Ray's identity, every modifier composed in *)
  precomputed : precomputed option;
  room : int;  (** the deepest the subdivision can go: the size of its stack *)
}

val make :
  Fn.t * Fn.t * Fn.t -> float * float -> float * float -> accuracy:float -> max_gradient:float -> container -> t
(** [make (fx, fy, fz) (u1, v1) (u2, v2) ~accuracy ~max_gradient c] is the surface as
    Parse_Parametric reads it (the bounds sorted; no transform, nothing precomputed). [accuracy]
    must be positive. *)

val transform : t -> Transform.t -> t
(** [transform s m] is Parametric::Transform: [m] composed into its transform. *)

val precompute : t -> depth:int -> x:bool -> y:bool -> z:bool -> t
(** [precompute s ~depth ~x ~y ~z] is Precompute_Parametric_Values ([depth] from 1 to 20) for the
    chosen functions, with the surface's final accuracy and max_gradient. *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w s o d lo] is the surface's crossing along the ray from [o] along the unit [d] when it
    is at least [lo], else infinity; its report left in [w.crossing]: the point and the (u, v)
    found (the corner of the piece found, Parametric::UVCoord's), no normal ([hit_normal]).
    Counted ("Parametric", "Parametric Bound"). *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w s id o d lo n] pushes that crossing (when it is at least [lo]) as a hit of the member
    [id], with its report (as [depth]'s); it is the new count. *)

val normal_at : t -> float -> float -> Vec.t
(** [normal_at s u v] is Parametric::Normal at (u, v): the cross product of the steps of the
    functions by [accuracy] in u and in v, through the transform, normalised. *)

val hit_normal : t -> Crossing.t -> Vec.t
(** [hit_normal s c] is the normal at the crossing reported as [c]: [normal_at] its (u, v). *)

val bounds : t -> float array
(** [bounds s] is the container's box, its corners mapped by the transform. *)

val pov_box : t -> float array
(** [pov_box s] is Parametric::Compute_BBox: Make_BBox of the container's box, then
    Recompute_BBox through the transform. *)

val traits : Traits.t
(** [traits] is its kind's traits: flat, without an inside, and [inverse] does nothing
    (Parametric::Invert). *)

val max_pieces : int
(** [max_pieces] is 20,000: the pieces one search may test before povml stops it with what it
    found (counted in [Stats.parametric_cut], warned of at the end of the render). A surface whose
    ranges are far wider than its max_gradient lets the search tell apart would otherwise be
    halved to the accuracy everywhere; POV-Ray's search, whose stack holds 32 pieces, runs on. *)
