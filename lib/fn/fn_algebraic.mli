(** The algebraic surfaces among POV-Ray 3.7's internal functions (fnintern.cpp): the algebraic
    cylinders, f_bicorn … f_witch_of_agnesi_2d, most of them a polynomial times a field strength
    clipped to ±10, the "_2d" ones optionally revolved about y (POV-Ray's SOR switch, offset and
    angle). Written in POV-Ray's order of operations. *)

val find : int -> (float array -> float) option
(** [find k] is the function of [internal(k)] if [k] is one of the algebraic surfaces (0–5, 8,
    11–16, 18, 20–23, 30, 31, 33–39, 41–46, 48–50, 54–56, 65–67, 71–75), else [None]. The function
    reads x, y, z at 0, 1, 2 of its array and the parameters from 3 ({!Fn_internal.arity} in all). *)
