(** A light source as the tracer uses it (docs/povray-rules.md §3.3, §3.4, §18.2, §18.3), and the
    samples of light it gives a lit point: local illumination asks a light for its samples and
    sends one shadow feeler per sample, so that a new kind of light is a new way of giving
    samples. *)

(** How a light's colour is attenuated by the lit point's place, besides fade (§3.4, §18.2). *)
type spread =
  | Everywhere  (** a point or parallel light: no cone, no beam *)
  | Spot of { radius_cos : float; falloff_cos : float; tightness : float }  (** a spotlight *)
  | Beam of { beam_radius : float; beam_falloff : float; beam_tightness : float }  (** a cylinder light *)

(** A light with its attenuation settings. *)
type t = {
  lx : float;
  ly : float;
  lz : float;  (** its centre *)
  lcolour : Rgb.t;  (** its colour, single precision *)
  shadowless : bool;  (** it casts no shadow and gives no highlights (§3.3) *)
  fade : bool;  (** fade_power > 0 and |fade_distance| > EPSILON (§3.4) *)
  lfade_distance : float;
  lfade_power : float;
  spread : spread;
  parallel : bool;  (** §18.3: light arrives along −dir, up to the plane through the centre *)
  dx : float;
  dy : float;
  dz : float;  (** the unit direction from the centre to point_at (§14.8) *)
}

val compile : Scene.light -> t
(** [compile l] is the light [l] as the tracer uses it: its colour in single precision, its
    direction normalize(point_at − centre) (left as it is when shorter than EPSILON, §14.8). *)

type sample = {
  mutable dx : float;
  mutable dy : float;
  mutable dz : float;  (** the unit direction from the lit point towards the light *)
  mutable dist : float;
      (** how far the light is along the direction: what a shadow feeler must cross (infinite for a
          light at an infinite distance; 0 or less behind a parallel light's plane, where nothing
          shadows) *)
  mutable atten : float;  (** the factor of the light's colour at the point: its cone, beam and fade *)
}
(** One sample of the light a point receives: where it comes from and how strong it is. A render
    worker owns one and {!sample} writes it (its fields are floats only, so that writing it
    allocates nothing). *)

val room : unit -> sample
(** [room ()] is a sample for a worker to be written by {!sample}. *)

val samples : t -> int
(** [samples light] is how many samples [light] gives a lit point: 1 for every light povml has
    (point, spot, cylinder and parallel lights). *)

val sample : t -> Vec.t -> int -> sample -> unit
(** [sample light p i s] writes into [s] the [i]th sample (from 0 to [samples light − 1]) of the
    light [p] receives from [light] (POV-Ray's ComputeOneWhiteLightRay and Attenuate_Light): the
    direction from [p] to the centre, made unit by the reciprocal of the distance (§3.3), or along
    −dir up to the plane through the centre for a parallel light (§18.3); the {!attenuation} of its
    colour. *)

val colour : t -> sample -> Rgb.t
(** [colour light s] is the light's colour the sample [s] brings: [light]'s colour times the
    sample's attenuation in single precision (the colour itself when the attenuation is 1). *)

val direction : sample -> Vec.t
(** [direction s] is the sample's direction as a vector. *)

val attenuation : t -> Vec.t -> Vec.t -> float -> float
(** [attenuation light p l dist] is the factor of [light]'s colour at the point [p] whose light ray
    has the unit direction [l] (towards the light) and length [dist] (§3.4, Attenuate_Light): the
    spotlight cone (cos^tightness, the cubic spline between the falloff and radius cosines, 0 behind),
    the cylinder beam, then fade. *)

val cubic_spline : float -> float -> float -> float
(** [cubic_spline lo hi p] is 0 below [lo], 1 from [hi] on, and (3 − 2s)s² with s = (p − lo)/(hi − lo)
    between: the soft edge of spotlights and cylinder lights (§3.4). *)

val parallel_depth : t -> Vec.t -> float -> float
(** [parallel_depth light l dist] is the length of a parallel light's ray from a point at distance
    [dist] from its centre in the unit direction [l]: the point's signed distance in front of the
    plane through the centre perpendicular to the light's direction (§18.3). *)
