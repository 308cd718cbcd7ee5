(** CSG kept whole (docs/povray-rules.md §16): union (with [split_union off]), merge, intersection and
    difference, and objects with [clipped_by] or [bounded_by]. A CSG's hits are its members' hits kept by its rule;
    its inside is its members' insides combined. The members are shapes again, so each function
    takes the member operation it recurses through ([Shape]'s) as an argument. *)

val is_csg : Compiled.shape -> bool
(** [is_csg s] is true for a CSG, false for a primitive. *)

val hits :
  all_hits:(Scratch.t -> Compiled.member -> Vec.t -> Vec.t -> float -> int -> int) ->
  inside:(float array -> Compiled.member -> Vec.t -> bool) ->
  Scratch.t -> Compiled.csg -> Vec.t -> Vec.t -> float -> int -> int
(** [hits ~all_hits ~inside w c o d lo n] appends to [w.hits], after its first [n], every hit at
    least [lo] that the CSG keeps (§16.2), in the order POV-Ray pushes them, and is the new count:
    a union keeps every hit of its members; an intersection a hit of member k whose point is
    inside every other member; a merge one inside no other member. A member's surviving hits are
    taken off its own stack, so they are pushed in reverse (intersection and merge). A clipped
    object keeps its hits inside every clip object, in the order it pushes them (Point_In_Clip); a
    clipped union, like an intersection, takes each member's hits off a stack of its own. A
    bounded object's hits are its own, when the ray meets every bounding object (their boxes
    tested first, then their hits at MIN_ISECT_DEPTH or beyond) or starts inside it
    (Ray_In_Bound); none otherwise. [all_hits] lists a member's hits, [inside] is a member's Inside test. *)

val depth :
  all_hits:(Scratch.t -> Compiled.member -> Vec.t -> Vec.t -> float -> int -> int) ->
  inside:(float array -> Compiled.member -> Vec.t -> bool) ->
  Scratch.t -> Compiled.csg -> Vec.t -> Vec.t -> float -> float
(** [depth ~all_hits ~inside w c o d lo] is the nearest kept hit, or infinity: the hits are popped
    from the stack, last pushed first, and the first of the smallest depth wins; the member hit is
    left in [w.leaf], its part in [w.part], its report (a julia fractal's, a bicubic patch's, a
    parametric surface's) in [w.crossing] and [w.reported]. The CSG's single-precision box is tested first
    (Trace::FindIntersection, §15.8): a ray grazing an edge of the box within its rounding misses
    the CSG. The robust mode decides by the geometry alone. *)

val depth_unboxed :
  all_hits:(Scratch.t -> Compiled.member -> Vec.t -> Vec.t -> float -> int -> int) ->
  inside:(float array -> Compiled.member -> Vec.t -> bool) ->
  Scratch.t -> Compiled.csg -> Vec.t -> Vec.t -> float -> float
(** [depth_unboxed] is [depth] without the test of the CSG's own box. *)

val inside : inside:(float array -> Compiled.member -> Vec.t -> bool) -> float array -> Compiled.csg -> Vec.t -> bool
(** [inside ~inside stack c p] is §16.3: inside any member (union, merge), or inside every member
    (intersection; a clipped object's Inside asks its clip objects too); a bounded object's is
    its own. *)

val bounds : bounds:(Compiled.shape -> float array option) -> Compiled.csg -> float array option
(** [bounds ~bounds c] is CSG::Compute_BBox: a union's or merge's box holds its members' boxes; an
    intersection's is the overlap of its members' that are not inverted (an inverted CSG, morphed,
    counts as inverted: its surfaces are bounded, its inside is not); None when unbounded. A plane
    is unbounded here (POV-Ray bounds an axis-aligned one on one side: that changes only
    equal-depth ties). An inverted primitive written alone, an intersection of itself, keeps the
    primitive's own box. POV-Ray bounds an intersection's quadrics last, each within the box of
    the other members. A bounded object's box is the overlap of its bounding objects' boxes
    when that is the smaller, by POV-Ray's single-precision volumes (Parse_Object_Mods). *)

val lone_inverted : Compiled.csg -> Compiled.member option
(** [lone_inverted c] is the member of an intersection that holds one inverted primitive alone (an
    inverted primitive written by itself), whose own box POV-Ray keeps. *)

val pov_box : pov_box:(Compiled.shape -> float array) -> Compiled.csg -> float array
(** [pov_box ~pov_box c] is the CSG's POV-Ray box, rounded as POV-Ray stores it; [[||]]
    when unbounded. A union or merge with a [cbox] has that box: POV-Ray computes it when the CSG
    is built and maps it by each later transform (the history kept in {!Scene.shape}'s [box]).
    Otherwise it is CSG::Compute_BBox from the members' POV-Ray boxes as they are now (for an
    intersection, their overlap: not the tighter boxes of [bounds]). An inverted primitive written
    alone keeps its own POV-Ray box. *)

val union_box : float array list -> float array
(** [union_box boxes] is a union's or merge's box from its members' POV-Ray boxes ([[||]] for an
    unbounded one): their extent, [[||]] when longer than CRITICAL_LENGTH on any axis. *)

val magnitude : Compiled.csg -> float
(** [magnitude c] is the largest magnitude of its members. *)
