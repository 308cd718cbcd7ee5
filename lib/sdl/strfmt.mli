(** String functions of the scene language (docs/povray-rules.md §11.2). *)

val str : float -> int -> int -> string
(** [str v l p] is [str(v, l, p)]: [p] decimals (6 when [p < 0]), padded
    to [|l|] characters with zeros ([l < 0]) or spaces. *)

val vstr : float array -> string -> int -> int -> string
(** [vstr terms sep l p] formats each term with [str] and joins them with [sep]. *)

val value : string -> float
(** [value s] is [val(s)]: the number at the start of [s], 0 when there is none. *)

val compare : string -> string -> int
(** [compare a b] is [strcmp(a, b)]: the difference of the first differing bytes, 0 when equal. *)
