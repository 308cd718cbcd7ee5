/* JPEG decoding through libjpeg for povml (lib/image/jpeg_file.ml), as POV-Ray's jpeg.cpp does
   it: an error manager that returns to the caller with libjpeg's message instead of printing it
   and exiting, 8-bit grey or RGB output, every allocation bounded before it is made.
   camlimages' binding prints libjpeg's messages on standard error and, on some damaged files
   ("Bogus Huffman table definition"), jumps back into a C frame that has already returned: a
   segmentation fault. */

#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <jpeglib.h>
#include <jerror.h>
#include <caml/alloc.h>
#include <caml/fail.h>
#include <caml/memory.h>
#include <caml/mlvalues.h>

struct povml_jpeg_error {
  struct jpeg_error_mgr pub;
  jmp_buf back;
  char message[JMSG_LENGTH_MAX];
  int ended_early; /* libjpeg's JWRN_JPEG_EOF: the data ended before the image */
};

/* read_error_exit (jpeg.cpp): the message kept, control back to the setjmp in the caller */
static void povml_jpeg_error_exit(j_common_ptr cinfo)
{
  struct povml_jpeg_error *e = (struct povml_jpeg_error *)cinfo->err;
  (*cinfo->err->format_message)(cinfo, e->message);
  longjmp(e->back, 1);
}

/* read_output_message (jpeg.cpp): warnings are not printed; the one that says the data ended
   early is remembered */
static void povml_jpeg_emit_message(j_common_ptr cinfo, int level)
{
  struct povml_jpeg_error *e = (struct povml_jpeg_error *)cinfo->err;
  if (level < 0) {
    if (cinfo->err->msg_code == JWRN_JPEG_EOF) e->ended_early = 1;
    cinfo->err->num_warnings++;
  }
}

/* povml_jpeg_decode data max_pixels max_bytes: (status, width, height, components, bytes) where
   status is 0 (bytes: the samples, row-major, [components] per pixel), 1 (more pixels than
   max_pixels or more bytes than max_bytes; width and height say how many) or 2 (bytes: libjpeg's
   message) */
value povml_jpeg_decode(value data, value max_pixels_v, value max_bytes_v)
{
  CAMLparam3(data, max_pixels_v, max_bytes_v);
  CAMLlocal2(result, bytes);
  /* volatile: read after a longjmp */
  unsigned char *volatile input = NULL;
  unsigned char *volatile output = NULL;
  volatile int status = 0;
  volatile unsigned long width = 0, height = 0, components = 0;
  unsigned long len = caml_string_length(data);
  unsigned long max_pixels = (unsigned long)Long_val(max_pixels_v);
  unsigned long max_bytes = (unsigned long)Long_val(max_bytes_v);
  struct jpeg_decompress_struct cinfo;
  struct povml_jpeg_error err;

  memset(&cinfo, 0, sizeof cinfo);
  memset(&err, 0, sizeof err);
  /* a copy the garbage collector cannot move */
  input = malloc(len > 0 ? len : 1);
  if (input == NULL) caml_raise_out_of_memory();
  memcpy(input, String_val(data), len);

  cinfo.err = jpeg_std_error(&err.pub);
  err.pub.error_exit = povml_jpeg_error_exit;
  err.pub.emit_message = povml_jpeg_emit_message;
  if (setjmp(err.back)) {
    status = 2;
  } else {
    jpeg_create_decompress(&cinfo);
    jpeg_mem_src(&cinfo, input, len);
    (void)jpeg_read_header(&cinfo, TRUE);
    /* grey stays grey, everything else becomes RGB (CMYK cannot: libjpeg refuses it) */
    if (cinfo.jpeg_color_space == JCS_GRAYSCALE) cinfo.out_color_space = JCS_GRAYSCALE;
    else if (cinfo.jpeg_color_space == JCS_CMYK || cinfo.jpeg_color_space == JCS_YCCK) {
      strcpy(err.message, "Unsupported color format in JPEG image");
      status = 2;
    } else cinfo.out_color_space = JCS_RGB;
    if (status == 0) {
      width = cinfo.image_width;
      height = cinfo.image_height;
      if (width == 0 || height == 0 || width > max_pixels / height) status = 1;
    }
    if (status == 0) {
      jpeg_start_decompress(&cinfo);
      width = cinfo.output_width;
      height = cinfo.output_height;
      components = cinfo.output_components;
      if (width == 0 || height == 0 || width > max_pixels / height || (components != 1 && components != 3)) status = 1;
      else if (width * height > max_bytes / components) status = 1;
    }
    if (status == 0) {
      unsigned long stride = width * components;
      output = malloc(stride * height);
      if (output == NULL) {
        strcpy(err.message, "not enough memory to decode the JPEG");
        status = 2;
      } else {
        while (cinfo.output_scanline < cinfo.output_height) {
          JSAMPROW row = output + (unsigned long)cinfo.output_scanline * stride;
          if (jpeg_read_scanlines(&cinfo, &row, 1) != 1) break;
        }
        /* a file that ends early: libjpeg's memory source pads it with an end marker and warns;
           POV-Ray's source manager gives libjpeg no such padding and the file is refused */
        if (cinfo.output_scanline == cinfo.output_height && !err.ended_early) (void)jpeg_finish_decompress(&cinfo);
        if (cinfo.output_scanline < cinfo.output_height || err.ended_early) {
          strcpy(err.message, "Premature end of JPEG file");
          status = 2;
        }
      }
    }
  }
  jpeg_destroy_decompress(&cinfo);
  free(input);
  if (status == 0) {
    bytes = caml_alloc_initialized_string(width * height * components, (const char *)output);
  } else if (status == 2) {
    bytes = caml_copy_string(err.message);
  } else {
    bytes = caml_copy_string("");
  }
  free(output);
  result = caml_alloc_tuple(5);
  Store_field(result, 0, Val_int(status));
  Store_field(result, 1, Val_long(width));
  Store_field(result, 2, Val_long(height));
  Store_field(result, 3, Val_long(components));
  Store_field(result, 4, bytes);
  CAMLreturn(result);
}
