(** The readers of the shapes that live in a module of their own under [lib/shapes]: each one reads
    the shape's own items, after its keyword and '{', and gives the scene shape; the object's
    modifiers are read after it by [Objects]. *)

val polygon : Reader.st -> Loc.t -> Scene.shape
(** [polygon st loc] reads [N, P1, …, PN] of [polygon { … }] written at [loc] (docs/povray-rules.md §15.7):
    N truncated to an integer, at least 3 (POV-Ray's fatal "Polygon needs at least three
    points"), the points 3-D or 2-D (z = 0), the commas optional; warns as POV-Ray does when the last
    outline is not closed, and (povml only) when the points make a degenerate polygon. *)

val quadric : Reader.st -> Scene.shape
(** [quadric st] reads [<A,B,C>, <D,E,F>, <G,H,I>, J] of [quadric { … }] (Parse_Quadric). *)

val poly : Reader.st -> order:int -> Scene.shape
(** [poly st ~order] reads the items of [poly { N, <…> }] when [order] is 0, of [cubic { <…> }]
    with 3, of [quartic { <…> }] with 4 (Parse_Poly): N truncated to an integer within 2 … 35
    (POV-Ray's fatal "Order of poly is out of range"), then '<', exactly (N+1)(N+2)(N+3)/6
    coefficients, the commas optional, and '>'. *)

val polynomial : Reader.st -> Scene.shape
(** [polynomial st] reads [N, xyz(i, j, k): c, …] of [polynomial { … }] (Parse_Polynom): the order
    as for [poly], then any number of terms, each setting the coefficient of x^i·y^j·z^k (the
    others 0); powers adding up to more than N are POV-Ray's fatal "Coefficient of polynom is out
    of range". *)
