(** The compile step: looks at the immutable scene once and builds what the tracer calls. *)

val scene : Scene.t -> Compiled.t
(** [scene s] is [s] compiled: flat shapes, constant surfaces, the shadow strategy this scene needs,
    and the camera's starting interior list (the objects whose bounding box and Inside test both
    contain the camera, §6.4). *)


val surface : legacy:bool -> noise:int -> ambient_light:Rgb.t -> Scene.layer -> Compiled.surface
(** [surface ~legacy ~noise ~ambient_light l] is the compiled surface of the layer [l]: its finish
    in single precision, its colour-dependent fields folded for a plain colour, or computed at each
    point for a pattern ([noise]: the scene's noise generator); [legacy] selects the formula of
    scenes before version 3.70. *)
