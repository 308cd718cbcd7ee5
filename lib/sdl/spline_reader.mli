(** The readers of the spline shapes: each reads the shape's own items after its keyword and '{'
    and gives the scene shape; the object's modifiers ([sturm] among them) are read after it by
    [Objects]. POV-Ray's checks are fatal errors at the point count or the point, with its
    messages. *)

val uv_vector : Reader.st -> float * float
(** [uv_vector st] is the ⟨u, v⟩ read next (Parse_UV_Vect): a float stands for both terms; any
    other value (more than two terms among them) is an error at its location. *)

val prism : Reader.st -> Loc.t -> Scene.shape
(** [prism st loc] reads [[SPLINE] [SWEEP] H1, H2, N, P1, …, PN [open]] of [prism { … }] at [loc]
    (Parse_Prism): the heights swapped when H1 > H2, N truncated (at least 3, 5 or 6 points for a
    linear, quadratic or cubic spline, a multiple of 4 for a Bezier one), the points ⟨u, v⟩, the
    commas optional; a linear outline not closed is closed with a warning, any other is kept as
    a degenerate prism (never hit) with POV-Ray's warning. *)

val lathe : Reader.st -> Loc.t -> Scene.shape
(** [lathe st loc] reads [[SPLINE] N, P1, …, PN] of [lathe { … }] (Parse_Lathe): at least 2, 3 or 4
    points, a multiple of 4 for Bezier; an inner point with a negative radius is an error. *)

val sor : Reader.st -> Loc.t -> Scene.shape
(** [sor st loc] reads [N, P1, …, PN [open]] of [sor { … }] (Parse_Sor): at least 4 points, no
    negative radius, heights increasing from the third point to the last but one. *)
