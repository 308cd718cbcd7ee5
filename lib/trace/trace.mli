(** The recursive Whitted tracer (docs/povray-rules.md §2–§7): the colour seen along one ray. *)

type result = Traced.t = { r : float; g : float; b : float; tr : float }
(** A traced colour, in the working colour space, with its transmittance (used only by the
    antialiasing comparison, §9.5). *)

type nonrec ctx = Context.t
(** What a trace reads and writes: one render worker's context. *)

val make_ctx : ?robust:bool -> Compiled.t -> Stats.t -> ctx
(** [make_ctx] is {!Context.make}: the context of a render worker's first block. *)

val renew_ctx : ctx -> carry:bool -> Stats.t -> ctx
(** [renew_ctx] is {!Context.renew}: the context of the worker's next block. *)

val black : result
(** [black] is what a ray cut off by max_trace_level or adc_bailout returns. *)

val trace_ray : ctx -> Ray.t -> result
(** [trace_ray ctx ray] is the colour seen along [ray] (§7): black past max_trace_level or below
    adc_bailout, the sky when nothing is hit, else the shaded surface. *)

val trace : ctx -> level:int -> weight:float -> interiors:int list -> continued:bool -> Vec.t -> Vec.t -> result
(** [trace ctx ~level ~weight ~interiors ~continued origin dir] is {!trace_ray} of the ray
    {!Ray.start} makes: from [origin] along the unit direction [dir], inside [interiors] (last
    entered first); a [continued] ray (ior 1 transmission) does not use up a trace level. *)
