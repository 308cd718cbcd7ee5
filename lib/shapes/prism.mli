(** The prism (POV-Ray's [shape/prism.cpp], [Parse_Prism]): a closed 2-D spline outline in the XZ
    plane of prism space (its points' u, v as x, z) swept along Y between [height1] and
    [height2], straight ([linear_sweep]) or scaled with the height towards the origin
    ([conic_sweep]); capped unless [open]. Placed by its transform (every modifier composes into
    it), the ray renormalised in prism space; depths in world units. *)

type spline = Linear | Quadratic | Cubic | Bezier  (** linear_spline … bezier_spline *)

type segment = {
  x1 : float;
  y1 : float;
  x2 : float;
  y2 : float;  (** the segment's bounding rectangle (x, z), widened to the heights for a conic sweep *)
  v1 : float;
  u2 : float;
  v2 : float;  (** its rectangle in ⟨u, v⟩, as in_curve tests it *)
  ax : float;
  ay : float;
  bx : float;
  by : float;
  cx : float;
  cy : float;
  dx : float;
  dy : float;  (** the cubic A·w³ + B·w² + C·w + D of each coordinate, w ∈ [0, 1] *)
}

type t = {
  spline : spline;
  conic : bool;  (** conic_sweep *)
  height1 : float;
  height2 : float;  (** the heights, the lower first *)
  closed : bool;  (** capped (not [open]) *)
  sturm : bool;
  degenerate : bool;  (** a non-linear outline that is not closed: never hit (POV-Ray ignores it) *)
  x1 : float;
  y1 : float;
  x2 : float;
  y2 : float;  (** the overall rectangle (x, z), conic-widened *)
  u1 : float;
  v1 : float;
  u2 : float;
  v2 : float;  (** the overall ⟨u, v⟩ rectangle of the outline *)
  segs : segment array;
  tr : Transform.t;  (** prism space to world *)
  pbox : float array;  (** [pov_box] of the prism as it stands, kept for the per-object box test *)
}

val close : spline -> (float * float) array -> (float * float) array * [ `Closed | `Closing | `Open ]
(** [close s pts] is Parse_Prism's closing check of the points as written: [`Closed] when every
    sub-outline ends on its first point; [`Closing] for a linear outline that does not (the last
    outline's first point is appended: POV-Ray's "Linear prism not closed. Closing it."); [`Open]
    otherwise ("Prism not closed. Ignoring it.": the prism is degenerate). A Bezier outline of no
    points is [`Closed] (POV-Ray reads memory outside its array there, and finds it closed). *)

val make :
  spline:spline -> conic:bool -> height1:float -> height2:float -> closed:bool -> sturm:bool -> degenerate:bool ->
  (float * float) array -> (t, string) result
(** [make … pts] is Compute_Prism of the points (after [close]): the segments' coefficients, their
    rectangles (the extremes of quadratic and cubic segments from their derivative's roots) and
    the overall ones, with the identity transform; [Error] with POV-Ray's message when the points
    run out in the middle of a segment ("Too few points in prism."). *)

val transform : t -> Transform.t -> t
(** [transform t m] composes [m] into the prism's transform (Prism::Transform). *)

val in_curve : t -> Polysolv.work -> float array -> float array -> float -> float -> bool
(** [in_curve t work c roots u v] is whether ⟨u, v⟩ is inside the outline: the crossings with the
    curve of the ray towards +u, counted (in_curve); [c] and [roots] are room for 4 and 3 floats. *)

val crossings : Scratch.t -> t -> Vec.t -> Vec.t -> int
(** [crossings w t o d] writes every crossing of the ray from [o] along the unit [d] into the curve
    room of [w] (Curve_hits), in POV-Ray's order (cap, base, then each segment's roots from the
    last), and returns their number: depths beyond 1e-4 (none in the robust mode), below 1e7;
    0 for a degenerate prism. The prism statistics are counted. *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w t o d lo] is the nearest crossing at least [lo] (its part in [w.part]), or infinity;
    as for a top-level object, only when the ray passes [Curve_hits.box_admits] of [t.pbox] (not in
    the robust mode). *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w t id o d lo n] pushes the crossings at least [lo] as hits of the member [id]. *)

val inside : t -> Vec.t -> bool
(** [inside t p] is Prism::Inside at the world point [p] (before any inversion): height1 ≤ y <
    height2 and the point (divided by y for a conic sweep) inside the outline. *)

val normal : t -> int -> Vec.t -> Vec.t
(** [normal t part p] is the unit normal at the world point [p] on [part]: ⟨0, 1, 0⟩ on a cap (the
    tracer turns it to the viewer), the rotated curve derivative on a segment, with a y that makes
    it perpendicular to the cone for a conic sweep; mapped by the inverse transpose. *)

val bounds : t -> float array
(** [bounds t] is the box of the mapped corners of the prism-space box. *)

val pov_box : t -> float array
(** [pov_box t] is Prism::Compute_BBox: Make_BBox of x1 … x2, height1 … height2, y1 … y2, mapped by
    the transform (Recompute_BBox). *)

val traits : Traits.t
(** [traits] is its kind's traits: [sturm] alone turns Sturm sequences on. *)
