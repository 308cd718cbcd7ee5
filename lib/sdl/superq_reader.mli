(** The readers of superellipsoid, ovus and sphere_sweep: each reads the shape's own items, after
    its keyword and '{', and gives the scene shape; [Objects] reads the modifiers after it. *)

val superellipsoid : Reader.st -> Scene.shape
(** [superellipsoid st] reads [<e, n>] (Parse_UV_Vect: a float stands for both) and sets up the
    powers 2/e, e/n, 2/n as Parse_Superellipsoid does. *)

val ovus : Reader.st -> Loc.t -> Scene.shape
(** [ovus st loc] reads [bottom, top] of [ovus { … }] written at [loc] (Parse_Ovus): an error when
    a radius is negative; a top radius of at least twice the bottom one gives, with POV-Ray's
    warning, the sphere it stands for (centre <0, bottom, 0>, radius top). *)

val sphere_sweep : Reader.st -> Scene.shape
(** [sphere_sweep st] reads [linear_spline | cubic_spline | b_spline, N, C1, R1, …, CN, RN
    \[tolerance T\]] of [sphere_sweep { … }] (Parse_Sphere_Sweep, commas optional): POV-Ray's
    errors "Invalid type of interpolation." and "Too few modeling spheres for interpolation
    type." (N truncated below 2, or below 4 for the cubic kinds). *)
