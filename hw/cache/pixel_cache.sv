// The HAD's cache (4.2.11.4): CACHE_PAGES pages (one in the thesis), each
// PAGE_PIXELS pixels x CELL_W bits (back-buffer R, G, B and Z; 16 x 40 in
// the thesis) with its page number, a valid and a dirty bit. Direct-mapped:
// page P lives in slot P mod CACHE_PAGES, the low bits of its X page index,
// so the pages side by side along a row are in the cache together. A page is
// loaded whole from VRAM and written one pixel at a time by the HAD.
// Lookups are combinational: the slot a page maps to (its page, valid,
// dirty, data), for the pixel at the FIFO's head, the pixel in hand and the
// slot being flushed.
module pixel_cache #(
    localparam int N = girtd_pkg::CACHE_PAGES, PIXELS = girtd_pkg::PAGE_PIXELS,
    localparam int CW = girtd_pkg::CELL_W, PW = PIXELS * CW,
    localparam int NW = girtd_pkg::PAGE_NUMBER_W, IW = girtd_pkg::PAGE_INDEX_W,
    localparam int SW = girtd_pkg::CACHE_SLOT_W
) (
    input  logic          clk_i,
    input  logic          rst_ni,
    // The slot the head pixel's page maps to: does it hold that page? What is in it?
    input  logic [NW-1:0] head_page_i,
    output logic          head_hit_o,
    output logic          head_slot_valid_o,
    output logic          head_slot_dirty_o,
    output logic [NW-1:0] head_slot_page_o,
    output logic [PW-1:0] head_slot_data_o,
    // The pixel in hand: the cell it reads (its page is in the cache while it is accessed).
    input  logic [NW-1:0] pix_page_i,
    input  logic [IW-1:0] pix_index_i,
    output logic [CW-1:0] pix_cell_o,
    // Slot `flush_slot_i`, written back at the end of a frame.
    input  logic [SW-1:0] flush_slot_i,
    output logic          flush_valid_o,
    output logic          flush_dirty_o,
    output logic [NW-1:0] flush_page_o,
    output logic [PW-1:0] flush_data_o,
    input  logic          invalidate_i,  // slot flush_slot_i
    // A page arriving from VRAM (into its slot), a pixel written (into pix_page_i's slot).
    input  logic          load_i,
    input  logic [NW-1:0] load_page_i,
    input  logic [PW-1:0] load_data_i,
    input  logic          write_i,
    input  logic [CW-1:0] write_data_i
);
  logic valid_q[N], dirty_q[N];
  logic [NW-1:0] page_q[N];
  logic [CW-1:0] cell_q[N][PIXELS];

  function automatic logic [SW-1:0] slot_of(input logic [NW-1:0] page);
    slot_of = SW'(32'(page) % N);
  endfunction

  logic [SW-1:0] head_slot, pix_slot, load_slot, flush_slot;
  assign head_slot = slot_of(head_page_i);
  assign pix_slot = slot_of(pix_page_i);
  assign load_slot = slot_of(load_page_i);
  assign flush_slot = SW'(32'(flush_slot_i) % N);

  always_ff @(posedge clk_i) begin
    for (int s = 0; s < N; s++) begin
      if (!rst_ni || (invalidate_i && 32'(flush_slot) == s)) valid_q[s] <= 1'b0;
      else if (load_i && 32'(load_slot) == s) valid_q[s] <= 1'b1;
    end
    if (load_i) begin
      page_q[load_slot] <= load_page_i;
      dirty_q[load_slot] <= 1'b0;
      for (int i = 0; i < PIXELS; i++) cell_q[load_slot][i] <= load_data_i[i*CW+:CW];
    end else if (write_i) begin
      cell_q[pix_slot][pix_index_i] <= write_data_i;
      dirty_q[pix_slot] <= 1'b1;
    end
  end

  assign head_slot_valid_o = valid_q[head_slot];
  assign head_slot_dirty_o = dirty_q[head_slot];
  assign head_slot_page_o = page_q[head_slot];
  assign head_hit_o = valid_q[head_slot] && page_q[head_slot] == head_page_i;
  assign pix_cell_o = cell_q[pix_slot][pix_index_i];
  assign flush_valid_o = valid_q[flush_slot];
  assign flush_dirty_o = dirty_q[flush_slot];
  assign flush_page_o = page_q[flush_slot];
  for (genvar i = 0; i < PIXELS; i++) begin : g_out
    assign head_slot_data_o[i*CW+:CW] = cell_q[head_slot][i];
    assign flush_data_o[i*CW+:CW] = cell_q[flush_slot][i];
  end

`ifdef FORMAL_PIXEL_CACHE  // tools/girtd formal, when this module is the one proven
`include "pixel_cache_formal.svh"
`endif
endmodule
