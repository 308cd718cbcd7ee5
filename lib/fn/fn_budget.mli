(** The steps user functions may take while a scene is read. A function called from the scene
    language runs its counting code ({!Fn.t.counted}), which takes steps from this one budget: at
    each entry into a compiled function as many as its body has operations, at each iteration of a
    [sum] or [prod] as many as the iterated expression has, and before an internal function whose
    octaves a parameter sets as many as it has octaves ({!Fn_internal.loop_parameter}). Rendering runs the code that does not
    count (its cost is bounded by the pixels), so the budget costs the renderer nothing.

    POV-Ray has no such bound: a sum of 10¹² terms or 64 functions each calling the one before
    twice run until killed. *)

exception Exhausted
(** Raised by {!take} when the budget is spent; the scene reader turns it into a located limit
    error at the call. *)

val start : int -> unit
(** [start n] gives the budget [n] steps (at the start of each scene). *)

val take : int -> unit
(** [take n] takes [n] steps from the budget; raises {!Exhausted} when fewer were left (and from
    then on). *)

val loops : float -> int
(** [loops v] is the steps of a loop a parameter [v] sets (octaves, tubes): [v] + 1, the most
    steps for a [v] too big to count, 1 for NaN or a negative [v]. *)
