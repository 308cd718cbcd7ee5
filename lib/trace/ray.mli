(** A ray as the tracer follows it (docs/lecture.md §1–§5): where it starts, where it goes, and
    what it carries from the rays before it. *)

(** Why a ray was sent: it decides which objects it can meet (docs/povray-rules.md §16.6), whether
    it uses up a trace level (§7) and what happens along it (§4, §6.3). *)
type kind =
  | Camera  (** from the eye through a pixel (§1.4) *)
  | Reflected  (** in the mirror direction, or after total internal reflection (§5.3, §6.2) *)
  | Transmitted  (** bent through an interface by Snell's law (§6.2) *)
  | Continued
      (** through an interface of equal indices: the same direction, at the same trace level (§6.2, §7) *)
  | Shadow  (** a shadow feeler from a lit point towards a light (§4) *)

type t = {
  origin : Vec.t;
  dir : Vec.t;  (** unit length, but for a refracted ray (§6.2: not renormalised) *)
  kind : kind;
  level : int;  (** the trace level of the hit it leaves (0 for a camera ray) *)
  weight : float;  (** its share of the pixel's colour, compared with adc_bailout (§7) *)
  interiors : int list;  (** the interiors it travels in, last entered first (§6.4) *)
  mirrored : bool;
      (** it or a ray before it was reflected: it meets what reflections see, else what the
          camera sees (§16.6, no_reflection and no_image) *)
}

val start : level:int -> weight:float -> interiors:int list -> continued:bool -> Vec.t -> Vec.t -> t
(** [start ~level ~weight ~interiors ~continued origin dir] is a ray from the eye's side of the
    scene: a [Camera] ray, or with [continued] a [Continued] one; it is not [mirrored]. *)
