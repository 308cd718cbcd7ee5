(** Three-channel colours (light, finish colours, traced results), stored unboxed. *)

type t = { r : float; g : float; b : float }

val make : float -> float -> float -> t
(** [make r g b] is the colour (r, g, b). *)

val black : t
(** [black] is (0, 0, 0). *)

val white : t
(** [white] is (1, 1, 1). *)

val grey : float -> t
(** [grey v] is (v, v, v). *)

val add : t -> t -> t
(** [add a b] is the channel-wise sum. *)

val mul : t -> t -> t
(** [mul a b] is the channel-wise product. *)

val scale : float -> t -> t
(** [scale s a] is s·a. *)

val max3 : t -> float
(** [max3 c] is the largest channel. *)

val intensity : t -> float
(** [intensity c] is 0.297 r + 0.589 g + 0.114 b, POV-Ray's grey (docs/povray-rules.md §3). *)

val is_zero : t -> bool
(** [is_zero c] is true when every channel is exactly 0. *)
