// The DDA -> HAD FIFO (4.2.11.2): built DEPTH deep, used up to a run-time
// limit so depth sweeps do not re-verilate. Full/empty flags; pushing into a
// full FIFO is an assertion failure.
module pixel_fifo #(
    parameter int W = girtd_pkg::FIFO_W,
    parameter int DEPTH = girtd_pkg::FIFO_MAX_DEPTH,
    localparam int CW = $clog2(DEPTH + 1)
) (
    input  logic          clk_i,
    input  logic          rst_ni,
    input  logic [CW-1:0] limit_i,  // 1 .. DEPTH entries
    input  logic          push_i,
    input  logic [W-1:0]  data_i,
    output logic          full_o,
    input  logic          pop_i,
    output logic [W-1:0]  data_o,
    output logic          empty_o,
    output logic [CW-1:0] count_o
);
  localparam int AW = $clog2(DEPTH);
  logic [W-1:0] mem_q[DEPTH];
  logic [AW-1:0] rd_q, wr_q;
  logic [CW-1:0] count_q;

  assign full_o = count_q >= limit_i;
  assign empty_o = count_q == '0;
  assign data_o = mem_q[rd_q];
  assign count_o = count_q;

  function automatic logic [AW-1:0] next_ptr(input logic [AW-1:0] p);
    next_ptr = (32'(p) == DEPTH - 1) ? '0 : p + 1'b1;
  endfunction

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      rd_q <= '0;
      wr_q <= '0;
      count_q <= '0;
    end else begin
      if (push_i) begin
        mem_q[wr_q] <= data_i;
        wr_q <= next_ptr(wr_q);
      end
      if (pop_i) rd_q <= next_ptr(rd_q);
      count_q <= count_q + CW'(push_i) - CW'(pop_i);
    end
  end

`ifndef SYNTHESIS
  always_ff @(posedge clk_i) begin
    if (rst_ni && push_i && full_o && !pop_i) $error("pixel_fifo: push into a full FIFO (overflow)");
    if (rst_ni && pop_i && empty_o) $error("pixel_fifo: pop from an empty FIFO");
  end
`endif

`ifdef FORMAL_PIXEL_FIFO  // tools/girtd formal, when this module is the one proven
`include "pixel_fifo_formal.svh"
`endif
endmodule
