(** The render loop: camera rays, antialiasing method 1 in blocks, and the split over processes. *)

type area = { left : int; right : int; top : int; bottom : int }
(** The pixels to render, 0-based and inclusive (a partial render, §10.3); the rest stays black. *)

type options = {
  width : int;
  height : int;
  antialias : float option;  (** threshold, or [None] for no antialiasing *)
  aa_depth : int;  (** +R: samples per side when supersampling, 1 … 9 *)
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

val camera_dir : Scene.camera -> int -> int -> float -> float -> Vec.t
(** [camera_dir cam w h x y] is the unit direction of the camera ray through pixel position (x, y)
    of a w×h image (§1.4); integer positions are pixel centres. *)

val render : options -> Compiled.t -> Scene.gamma -> Image.t * Stats.t
(** [render opts scene gamma] traces the image and returns it with the merged statistics. *)
