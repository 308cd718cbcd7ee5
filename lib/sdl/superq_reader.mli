(** The readers of superellipsoid, ovus and sphere_sweep: each reads the shape's own items, after
    its keyword and '{', and gives the scene shape; [Objects] reads the modifiers after it. *)

val superellipsoid : Reader.st -> Scene.shape
(** [superellipsoid st] reads [<e, n>] (Parse_UV_Vect: a float stands for both) and sets up the
    powers 2/e, e/n, 2/n as Parse_Superellipsoid does. *)
