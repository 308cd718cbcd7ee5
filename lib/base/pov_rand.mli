(** crand's random stream: POV-Ray's POV_rand (support/randomsequences.cpp), one per render
    thread and never reset, so that its values run on from block to block in render order
    (docs/povray-rules.md §3.3). A render worker owns one ({!Context.t.crand}). *)

type t
(** A stream and its 32-bit state. *)

val create : unit -> t
(** [create ()] is a stream at its start: state 0, as a new render thread's. *)

val next : t -> float
(** [next s] is the stream's next value, in [0, 1]: its state becomes
    state·1812433253 + 12345 (mod 2³²), divided by 4294967295. *)
