// The HAD's cache (4.2.11.4): one page of PAGE_PIXELS pixels x CELL_W bits
// (back-buffer R, G, B and Z; 16 horizontal pixels x 40 bits in the thesis),
// its page number (the VRAM address without the pixel in the page) and a
// valid bit. Loaded whole from VRAM, written one pixel at a time by the HAD.
module pixel_cache (
    input  logic                                              clk_i,
    input  logic                                              rst_ni,
    input  logic                                              invalidate_i,
    input  logic                                              load_i,
    input  logic [girtd_pkg::PAGE_NUMBER_W-1:0]               load_page_i,
    input  logic [girtd_pkg::PAGE_PIXELS*girtd_pkg::CELL_W-1:0] load_data_i,
    input  logic                                              write_i,
    input  logic [girtd_pkg::PAGE_INDEX_W-1:0]                write_index_i,
    input  logic [girtd_pkg::CELL_W-1:0]                      write_data_i,
    output logic                                              valid_o,
    output logic [girtd_pkg::PAGE_NUMBER_W-1:0]               page_o,
    output logic [girtd_pkg::PAGE_PIXELS*girtd_pkg::CELL_W-1:0] data_o
);
  localparam int N = girtd_pkg::PAGE_PIXELS, CW = girtd_pkg::CELL_W;
  logic valid_q;
  logic [girtd_pkg::PAGE_NUMBER_W-1:0] page_q;
  logic [CW-1:0] cell_q[N];

  always_ff @(posedge clk_i) begin
    if (!rst_ni || invalidate_i) valid_q <= 1'b0;
    else if (load_i) valid_q <= 1'b1;
    if (load_i) begin
      page_q <= load_page_i;
      for (int i = 0; i < N; i++) cell_q[i] <= load_data_i[i*CW+:CW];
    end else if (write_i) begin
      cell_q[write_index_i] <= write_data_i;
    end
  end

  assign valid_o = valid_q;
  assign page_o = page_q;
  for (genvar i = 0; i < N; i++) begin : g_out
    assign data_o[i*CW+:CW] = cell_q[i];
  end
endmodule
