(** Camera, global settings, sky_sphere and background (docs/povray-rules.md §1, §7, §8). *)

val empty_camera : Reader.camera_spec
(** [empty_camera] is a camera with nothing written. *)

val parse_camera : Reader.st -> Reader.camera_spec
(** [parse_camera st] reads a camera block (after the keyword). *)

val build_camera : Reader.st -> Reader.camera_spec -> Scene.camera
(** [build_camera st c] applies the rules of §1.3 and the camera's transforms. *)

val parse_max_trace_level : Reader.st -> Loc.t -> unit
(** [parse_max_trace_level st loc] reads the number after [max_trace_level] (written at [loc]) into
    [st], clipped to 1 … 256 as POV-Ray does. *)

val parse_global_settings : Reader.st -> unit
(** [parse_global_settings st] reads a global_settings block (after the keyword). *)

val parse_sky : Reader.st -> Scene.sky
(** [parse_sky st] reads a sky_sphere block after its keyword: a declared sky_sphere first, if
    any, to which its pigments are added. *)

val parse_sky_sphere : Reader.st -> unit
(** [parse_sky_sphere st] reads a sky_sphere (the keyword is the next token). *)

val parse_background : Reader.st -> unit
(** [parse_background st] reads a background (the keyword is the next token). *)

val parse_radiosity_importance : Reader.st -> unit
(** [parse_radiosity_importance st] reads the block of a [radiosity] in [#default] or an object,
    after the keyword: its [importance] values, each checked to lie in (0, 1]. povml has no
    radiosity, so nothing else reads them. *)
