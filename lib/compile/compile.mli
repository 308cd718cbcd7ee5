(** The compile step: looks at the immutable scene once and builds what the tracer calls. *)

val pov_bounding_threshold : int
(** 1: POV-Ray's Bounding_Threshold when no ini file sets it (Debian's povray.ini sets 3). *)

val scene : ?bounding_threshold:int -> Scene.t -> Compiled.t
(** [scene ~bounding_threshold s] is [s] compiled: flat shapes, constant surfaces, the shadow
    strategy this scene needs, and the camera's starting interior list (the objects whose bounding
    box and Inside test both contain the camera, §6.4). POV-Ray's bounding tree, whose order
    decides exact ties, is used when the scene has at least [bounding_threshold] (default
    {!pov_bounding_threshold}) objects and light sources together; [max_int] never uses it
    (Bounding=off). *)


val surface : legacy:bool -> noise:int -> ambient_light:Rgb.t -> Scene.layer -> Compiled.surface
(** [surface ~legacy ~noise ~ambient_light l] is the compiled surface of the layer [l]: its finish
    in single precision, its colour-dependent fields folded for a plain colour, or computed at each
    point for a pattern ([noise]: the scene's noise generator); [legacy] selects the formula of
    scenes before version 3.70. *)
