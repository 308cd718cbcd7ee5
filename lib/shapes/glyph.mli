(** One letter of a [text] object (docs/povray-rules.md §15.9): a TrueType glyph outline in the plane z = 0
    of its own space, in em units, extruded from z = 0 to z = [depth], mapped to the world by its
    transform. Rays are brought into glyph space without renormalising the direction, so a
    glyph-space parameter is a world depth. The arithmetic and tolerances are POV-Ray's
    (TrueType::GlyphIntersect, Inside_Glyph, solve_quad), so edges fall where POV-Ray's do. *)

(** An outline: its contours flattened into segments, in the order POV-Ray walks them. *)
type outline = {
  segs : float array;
      (** 7 floats per segment: kind (0 a line, 1 a quadratic curve), then x0, y0, x1, y1, x2, y2
          (a line uses the first two points; a curve's off-curve control point is (x1, y1) and its
          end (x2, y2), the midpoint of two consecutive control points where the font implies one) *)
  nseg : int;
  contours : int;  (** the number of contours (0 for a space) *)
  xmin : int;
  ymin : int;
  xmax : int;
  ymax : int;  (** the glyph's box as POV-Ray keeps it in its header, in font units *)
  units_per_em : int;
}

type t = {
  outline : outline;
  depth : float;  (** the extrusion: the glyph fills 0 ≤ z ≤ depth *)
  tr : Transform.t;  (** glyph space to world *)
}

val outline_of_contours : units_per_em:int -> xmin:int -> ymin:int -> xmax:int -> ymax:int -> (float array * float array * bool array) list -> outline
(** [outline_of_contours ~units_per_em ~xmin ~ymin ~xmax ~ymax cs] is the outline of the contours
    [cs], each its points' x and y (em units) and on-curve flags, in the file's order. *)

val tolerance : float
(** 1e-6: a glyph keeps only hits beyond this depth (TTF_Tolerance). *)

val crossings : t -> Vec.t -> Vec.t -> float array -> int
(** [crossings g o d out] writes every crossing of the ray from [o] along [d] (world space) with the
    glyph beyond [tolerance], as (depth, part) pairs, into [out] and returns their number, in the
    order POV-Ray's All_Intersections pushes them: the front face (z = 0), the back face
    (z = depth), then the walls contour by contour. [out] needs room for [max_hits g]. *)

val max_hits : outline -> int
(** [max_hits o] bounds the number of crossings [crossings] can report, times 2 (the room it needs). *)

val normal : t -> int -> Vec.t
(** [normal g part] is the unit world normal of the part hit ([part] as [crossings] reports it): the
    face's ∓z, a line's (dy, −dx), a curve's derivative turned a quarter, by the inverse transpose,
    normalised (§14.6). *)

val inside_outline : outline -> float -> float -> bool
(** [inside_outline o x y] is POV-Ray's Inside_Glyph: whether a ray from (x, y) along +x crosses the
    outline an odd number of times. *)

val inside : t -> Vec.t -> bool
(** [inside g p] is POV-Ray's TrueType::Inside of the world point [p]: 0 ≤ z ≤ depth and inside
    the outline. *)

val box : t -> float array
(** [box g] is the glyph-space box [[| xmin; ymin; −1e-6; xmax; ymax; depth + 1e-6 |]]
    (the header's box over units_per_em), before the transform. *)

val depth : Scratch.t -> t -> Vec.t -> Vec.t -> float -> float
(** [depth w g o d lo] is the nearest crossing at least [lo] (the first of equal ones), its part
    left in [w.part]; or infinity. The test and a hit are counted ("True Type Font"). *)

val hits : Scratch.t -> t -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w g id o d lo n] pushes the crossings at least [lo] as hits of the member [id], the faces
    then the walls in the order found (TrueType::All_Intersections); it is the new count. *)

val bounds : t -> float array
(** [bounds g] is the box of [box g]'s mapped corners. *)

val pov_box : t -> float array
(** [pov_box g] is TrueType::Compute_BBox: Make_BBox of [box g] (z from −1e-6 to depth + 1e-6),
    then Recompute_BBox through the letter's whole transform (§15.9). *)

val traits : Traits.t
(** [traits] is its kind's traits (a letter of a text object): [Traits.default]. *)
