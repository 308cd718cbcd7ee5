(** The julia fractal (POV-Ray's shape/fractal.cpp, math/quatern.cpp, math/hcmplx.cpp): the 3-D
    slice [slice · (x, y, z, w) = slice_dist] of the 4-D Julia set of [z → f(z) + c] in the
    quaternions or the hypercomplex numbers, the points whose iterates stay within the escape
    value for [iterations] steps. Placed by its own transform, bounded by a sphere about its
    origin. *)

type algebra = Quaternion | Hypercomplex

(** The map: [sqr] (the default), [cube], [reciprocal] (hypercomplex only), or a complex function
    applied through the duplex form (hypercomplex only). *)
type func = Sqr | Cube | Reciprocal | Func of Julia_algebra.func

type t = {
  p0 : float;
  p1 : float;
  p2 : float;
  p3 : float;  (** c, the julia parameter <a, b, c, d> *)
  s0 : float;
  s1 : float;
  s2 : float;
  s3 : float;  (** the slice's unit 4-D normal (its t part never 0) *)
  slice_dist : float;
  iterations : int;  (** [max_iteration], at least 1 (default 20) *)
  precision : float;  (** 1 / [precision] (at least 1; default 1/20): the least step of the march *)
  algebra : algebra;
  func : func;
  ex : float;
  ey : float;  (** the exponent of [pwr] *)
  inverted : bool;
      (** Fractal::Invert's own flag (not POV-Ray's INVERTED_FLAG): it only negates Inside, and
          Compute_BBox clears it, so that any later transform (or the end of the object's block)
          undoes an [inverse] *)
  trans : Transform.t option;  (** fractal space to world, from the first modifier on *)
  radius : float;  (** the bounding sphere's radius: 1 + |c| (+1e-7), at most 2; 4 for hypercomplex *)
  radius_sq : float;
  exit_value : float;  (** the escape value of the squared norm: R² + 1e-7; 16 for hypercomplex *)
}

val make :
  parm:float array ->
  slice:float array ->
  slice_dist:float ->
  iterations:int ->
  precision:float ->
  algebra:algebra ->
  func:func ->
  exponent:float * float ->
  t
(** [make ~parm ~slice ~slice_dist ~iterations ~precision ~algebra ~func ~exponent] is the fractal
    as Parse_Julia_Fractal leaves it (SetUp_Fractal's Compute_BBox done: not inverted). *)

val set_up : t -> t
(** [set_up f] is Compute_BBox (as SetUp_Fractal runs it): the radius and escape value from the
    parameter and the algebra, [inverted] cleared. *)

val supported : algebra -> func -> bool
(** [supported a f] is whether SetUp_Fractal accepts the map [f] in the algebra [a] (quaternions:
    [sqr] and [cube] only). *)

val transform : t -> Transform.t -> t
(** [transform f m] is Fractal::Transform: [m] composed into its transform, Compute_BBox run again
    (which clears [inverted]). *)

val invert : t -> t
(** [invert f] is Fractal::Invert: [inverted] toggled. *)

val tolerance : float
(** 1e-7, fractal.cpp's Fractal_Tolerance: the least depth, the bisection's end. *)

val iterate : t -> float array -> float -> float -> float -> bool
(** [iterate f st x y z] is the fractal's Iteration of the fractal-space point: whether it stays
    in the set, its iterates left in [st] (4 floats each, room for [iterations + 1]). As POV-Ray's
    Iteration_HCompl_Func does, a function map starts from (x, y, y). *)

val d_iterate : t -> float array -> float -> float -> float -> float * float * float -> float
(** [d_iterate f st x y z dir] is D_Iteration: the distance to step from the point along [dir]
    (fractal space), negated when the point stays in the set (the precision then). *)

val raw_normal : t -> float array -> int -> Vec.t
(** [raw_normal f st n] is Normal_Calc over the first [n] iterates in [st]: the fractal-space
    gradient, not normalised. *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w f o d lo] is the first crossing the march finds along the ray from [o] along the unit
    [d] (world depth), as a fractal outside CSG stops at it, or infinity (also when it is below
    [lo]); its report left in [w.crossing] (Real_Pt, the fractal-space point mapped to the
    world, and the normal POV-Ray computes there: Normal_Calc on the iteration stack as the march
    left it, where the last Iteration escaped, what deeper iterations left counting); counted
    ("Fractal"). *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w f id o d lo n] pushes every crossing the march finds, at least [lo], as hits of the
    member [id] at POV-Ray's intersection points (the fractal-space point mapped back), each with
    its report (as [depth]'s); it is the new count. After the first crossing POV-Ray's depths lag behind the points, as they do here. *)

val inside : float array -> t -> Vec.t -> bool
(** [inside stack f p] is Fractal::Inside of the world point [p] ([stack] used as the iteration
    stack when it has room). *)

val normal : t -> Vec.t -> Vec.t
(** [normal f p] is the unit normal at the world point [p]: Iteration there, Normal_Calc over
    every iteration, MTransNormal, normalised (at a crossing POV-Ray's is the one its march
    reports, which may differ: see [depth]). *)

val bounds : t -> float array
(** [bounds f] is the box of the bounding sphere's cube mapped by the transform. *)

val pov_box : t -> float array
(** [pov_box f] is Fractal::Compute_BBox: Make_BBox of [−R … R] on each axis, then Recompute_BBox
    through the transform when there is one. *)

val traits : Traits.t
(** [traits] is its kind's traits: [inverse] toggles the fractal's own flag (Fractal::Invert),
    which its Inside holds. *)
