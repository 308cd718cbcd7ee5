(** The geometric internal functions of POV-Ray 3.7 (fnintern.cpp): spheres, tori, the rounded
    box, ellipsoids and blends of exponentials, blobs, helices, the helical torus, the spiral,
    the mesh, the hexagonal tilings, the comma, the quantum orbital, f_r, f_ph and f_th. Written
    in POV-Ray's order of operations, with its guards on the y axis. *)

val find : int -> (float array -> float) option
(** [find k] is the function of [internal(k)] if [k] is one of these (6, 7, 9, 10, 17, 19,
    24–28, 32, 40, 47, 51–53, 57, 60–64, 68–70), else [None]. The function reads x, y, z at 0,
    1, 2 of its array and the parameters from 3 ({!Fn_internal.arity} in all). *)
