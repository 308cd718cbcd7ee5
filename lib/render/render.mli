(** The render loop: antialiasing methods 1 and 2 in blocks, each sample a camera ray
    ({!Camera}) traced, and the split over processes. *)

type area = { left : int; right : int; top : int; bottom : int }
(** The pixels to render, 0-based and inclusive (a partial render, §10.3); the rest stays black. *)

type aa_method =
  | Non_adaptive  (** +AM1: a pixel differing from a neighbour gets a fixed depth×depth grid (§9.3) *)
  | Adaptive  (** +AM2: the four pixel corners, the pixel split in four where they differ, up to depth−1 times (§9.4) *)

type options = {
  width : int;
  height : int;
  antialias : float option;  (** threshold, or [None] for no antialiasing *)
  aa_method : aa_method;  (** used when [antialias] is set *)
  aa_depth : int;  (** +R, 1 … 9: samples per side (method 1); at most depth−1 subdivisions (method 2) *)
  jitter : float;  (** jitter amount, 0 without jitter *)
  aa_gamma : float;  (** colours are compared after x ↦ x^(1/aa_gamma) *)
  area : area;
  block_size : int;  (** 32 in POV-Ray; the antialiasing result depends on it (§9.3) *)
  workers : int;  (** processes; the image does not depend on it *)
  progress : bool;  (** print a progress line on stderr *)
  robust : bool;
      (** robust mode: hit limits and secondary-ray origins from floating-point error bounds instead
          of POV-Ray's fixed 1e-4 / 1e-3 (the default, [false], is exactly POV-Ray's) *)
}

val full_area : int -> int -> area
(** [full_area w h] is the whole image. *)

val defaults : int -> int -> options
(** [defaults w h] is POV-Ray's defaults for a w×h image: no antialiasing (method 1, depth 3,
    jitter 1, gamma 2.5 when turned on), 32-pixel blocks, the POV-Ray mode; one worker, no
    progress line. *)

val render : options -> Compiled.t -> Scene.gamma -> Image.t * Stats.t
(** [render opts scene gamma] traces the image and returns it with the merged statistics. *)
