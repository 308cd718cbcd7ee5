(** POV-Ray's internal functions (placeholder until the port lands). *)

val count : int
(** [count] is the number of internal functions. *)

val arity : int -> int
(** [arity k] is the parameter count of internal(k). *)

val name : int -> string
(** [name k] is functions.inc's name of internal(k). *)

val make : noise_generator:int -> int -> (float array -> float) option
(** [make ~noise_generator k] is internal(k)'s implementation. *)
