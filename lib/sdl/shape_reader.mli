(** The readers of the shapes that live in a module of their own under [lib/shapes]: each one reads
    the shape's own items, after its keyword and '{', and gives the scene shape; the object's
    modifiers are read after it by [Objects]. *)

val polygon : Reader.st -> Loc.t -> Scene.shape
(** [polygon st loc] reads [N, P1, …, PN] of [polygon { … }] written at [loc] (POVRAY-3.7 §15.7):
    N truncated to an integer, at least 3 (POV-Ray's fatal "Polygon needs at least three
    points"), the points 3-D or 2-D (z = 0), the commas optional; warns as POV-Ray does when the last
    outline is not closed, and (povml only) when the points make a degenerate polygon. *)

val quadric : Reader.st -> Scene.shape
(** [quadric st] reads [<A,B,C>, <D,E,F>, <G,H,I>, J] of [quadric { … }] (Parse_Quadric). *)
