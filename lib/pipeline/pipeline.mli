(** The whole path from a scene file to an encoded image, for the command line and the tests. *)

type result = {
  image : Encode.t;
  raw : Image.t;  (** the float image the tracer produced, before encoding *)
  stats : Stats.t;
  warnings : Error.t list;
  scene : Scene.t;  (** the scene read, its settings without its objects (let go once compiled) *)
  includes : (string * float) list;  (** the files the scene included, with the seconds each took *)
  parse_seconds : float;  (** reading the scene, meshes and their hierarchies included *)
  build_seconds : float;  (** the compile step: the scene's hierarchy, the surfaces *)
  render_seconds : float;  (** tracing and encoding *)
}

val run : ?interp:Interp.options -> ?move:float * Vec.t -> ?bounding_threshold:int -> Render.options -> string -> result
(** [run ?interp ?move ?bounding_threshold opts path] interprets (with [interp], whose size is
    replaced by [opts]'), moves the whole scene when [move] = (scale, translation) is given
    ([Place.scene]), compiles (with POV-Ray's Bounding_Threshold, {!Compile.scene}),
    renders and encodes the scene file [path].
    Raises [Error.Scene_error] for errors in the scene. *)
