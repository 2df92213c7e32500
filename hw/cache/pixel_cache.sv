// The HAD's cache (4.2.11.4): one page of 16 horizontal pixels x 40 bits
// (back-buffer R, G, B and Z), its page tag (A4-A19 = Y:X[9:4]) and a valid
// bit. Loaded whole from VRAM, written one pixel at a time by the HAD.
module pixel_cache (
    input  logic           clk_i,
    input  logic           rst_ni,
    input  logic           invalidate_i,
    input  logic           load_i,
    input  logic [15:0]    load_page_i,
    input  logic [16*40-1:0] load_data_i,
    input  logic           write_i,
    input  logic [3:0]     write_index_i,
    input  logic [39:0]    write_data_i,
    output logic           valid_o,
    output logic [15:0]    page_o,
    output logic [16*40-1:0] data_o
);
  logic valid_q;
  logic [15:0] page_q;
  logic [39:0] cell_q[16];

  always_ff @(posedge clk_i) begin
    if (!rst_ni || invalidate_i) valid_q <= 1'b0;
    else if (load_i) valid_q <= 1'b1;
    if (load_i) begin
      page_q <= load_page_i;
      for (int i = 0; i < 16; i++) cell_q[i] <= load_data_i[i*40+:40];
    end else if (write_i) begin
      cell_q[write_index_i] <= write_data_i;
    end
  end

  assign valid_o = valid_q;
  assign page_o = page_q;
  for (genvar i = 0; i < 16; i++) begin : g_out
    assign data_o[i*40+:40] = cell_q[i];
  end
endmodule
