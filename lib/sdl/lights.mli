(** The light_source block: point lights, spotlights, cylinder and parallel lights, and a light's
    looks_like object (docs/povray-rules.md §10.2, §18.2, §18.3, §19.2). *)

(** A light source as read: alone, or with its looks_like object (§19.2), kept as a union of the
    light and the object so that later transforms move both. *)
type light_source = Lone of Scene.light | Shaped of Value.obj

val parse :
  Reader.st ->
  object_:(Reader.st -> Value.obj) ->
  mods:(Reader.st -> Value.obj -> string -> Value.obj) ->
  light_source
(** [parse st ~object_ ~mods] reads a light_source, the keyword being the next token; [object_]
    reads the object of a looks_like and [mods st o "looks_like"] the modifiers after it, up to
    its closing brace. *)
