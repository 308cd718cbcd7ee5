(** What a ray brings back: a colour in the working colour space and its transmittance (used only
    by the antialiasing comparison, docs/povray-rules.md §9.5). *)

type t = { r : float; g : float; b : float; tr : float }

val black : t
(** [black] is what a ray cut off by max_trace_level or adc_bailout brings back. *)
