// Cover points of hw/fifo/pixel_fifo for its unit bench, bound into every
// instance (testbench/units/README.md): the cases a FIFO's bugs hide in.
module pixel_fifo_cover #(
    parameter int DEPTH = 2,
    localparam int CW = $clog2(DEPTH + 1), AW = $clog2(DEPTH)
) (
    input logic          clk_i,
    input logic          rst_ni,
    input logic [CW-1:0] limit_i,
    input logic          push_i,
    input logic          pop_i,
    input logic          full_o,
    input logic          empty_o,
    input logic [CW-1:0] count_q,
    input logic [AW-1:0] rd_q,
    input logic [AW-1:0] wr_q
);
  cover property (@(posedge clk_i) rst_ni && empty_o && !push_i);            // empty, idle
  cover property (@(posedge clk_i) rst_ni && empty_o && push_i);             // a push into an empty FIFO
  cover property (@(posedge clk_i) rst_ni && full_o && !pop_i);              // full, held
  cover property (@(posedge clk_i) rst_ni && full_o && pop_i && push_i);     // full: pop and push on one tick
  cover property (@(posedge clk_i) rst_ni && !full_o && !empty_o && push_i && pop_i);
  cover property (@(posedge clk_i) rst_ni && 32'(count_q) == DEPTH);         // built depth used up
  cover property (@(posedge clk_i) rst_ni && full_o && 32'(limit_i) < DEPTH);  // full at a run-time limit below it
  cover property (@(posedge clk_i) rst_ni && push_i && 32'(wr_q) == DEPTH - 1);  // the write pointer wraps
  cover property (@(posedge clk_i) rst_ni && pop_i && 32'(rd_q) == DEPTH - 1);   // the read pointer wraps
  cover property (@(posedge clk_i) rst_ni && 32'(limit_i) == 1 && full_o);   // one entry deep
endmodule

bind pixel_fifo pixel_fifo_cover #(.DEPTH(DEPTH)) u_cover (.*);
