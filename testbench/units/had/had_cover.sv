// Cover points of hw/had for its unit bench (testbench/units/README.md),
// bound into the unit: every state, every outcome of a pixel, and the
// memory side's cases (a hit, a miss with and without a write-back, the
// write-behind register, a prefetch used and waited for, the VRAM
// taken between a write-back and its fetch, the frame-end flush).
module had_cover (
    input logic       clk_i,
    input logic       rst_ni,
    input logic       fifo_empty_i,
    input logic       fifo_pop_o,
    input logic [2:0] state_q,
    input logic [girtd_pkg::LONG_TIME_W-1:0] ticks_i,
    input logic       head_hit,
    input logic       miss_go,
    input logic       miss_wait_pf,
    input logic       must_write_back,
    input logic       write_behind_i,
    input logic       wb_issue,
    input logic       pf_issue,
    input logic       pf_valid_q,
    input logic       head_in_pf,
    input logic       flush_step,
    input logic       flush_valid,
    input logic       flush_write_back,
    input logic       z_pass,
    input logic [girtd_pkg::TIME_W-1:0] count_q,
    input logic [girtd_pkg::NF_W-1:0] nf,
    input logic       opaque,
    input logic       cache_write
);
  localparam logic [2:0] H_IDLE = 3'd0, H_WB = 3'd1, H_FETCH = 3'd2, H_ACCESS = 3'd3, H_BLEND = 3'd4,
                         H_FLUSH = 3'd5, H_REFETCH = 3'd6;
  // What the exclusion of the case defaults (coverage_exclusions.json) rests
  // on: out of reset, state_q holds one of the seven states.
  assert property (@(posedge clk_i) rst_ni |-> state_q <= H_REFETCH);
  cover property (@(posedge clk_i) rst_ni && state_q == H_WB);
  cover property (@(posedge clk_i) rst_ni && state_q == H_FETCH);
  cover property (@(posedge clk_i) rst_ni && state_q == H_REFETCH);  // the VRAM taken between write-back and fetch
  cover property (@(posedge clk_i) rst_ni && state_q == H_BLEND);
  cover property (@(posedge clk_i) rst_ni && state_q == H_FLUSH);
  cover property (@(posedge clk_i) rst_ni && state_q == H_IDLE && fifo_pop_o && head_hit);           // a page hit
  cover property (@(posedge clk_i) rst_ni && miss_go && !must_write_back);                           // a clean miss
  cover property (@(posedge clk_i) rst_ni && miss_go && must_write_back && !write_behind_i);          // write back, then fetch
  cover property (@(posedge clk_i) rst_ni && miss_go && must_write_back && write_behind_i);           // into write-behind
  cover property (@(posedge clk_i) rst_ni && wb_issue && state_q != H_IDLE);                         // write-behind drained under a pixel
  cover property (@(posedge clk_i) rst_ni && pf_issue);                                              // a prefetch starts
  cover property (@(posedge clk_i) rst_ni && miss_go && pf_valid_q && head_in_pf);                  // a prefetch hit
  cover property (@(posedge clk_i) rst_ni && state_q == H_IDLE && !fifo_empty_i && !head_hit && miss_wait_pf);  // a miss waits for its prefetch
  cover property (@(posedge clk_i) rst_ni && state_q == H_ACCESS && !z_pass);                       // Z-rejected
  cover property (@(posedge clk_i) rst_ni && state_q == H_ACCESS && cache_write && opaque);          // written
  cover property (@(posedge clk_i) rst_ni && state_q == H_ACCESS && count_q == 1 && z_pass && nf == '0);  // dropped (nf = 0)
  cover property (@(posedge clk_i) rst_ni && state_q == H_ACCESS && cache_write && !opaque);         // blended with no blend time
  cover property (@(posedge clk_i) rst_ni && flush_step && flush_valid && flush_write_back);         // a page flushed to VRAM
  cover property (@(posedge clk_i) rst_ni && flush_step && flush_valid && !flush_write_back);        // a clean page forgotten
  cover property (@(posedge clk_i) rst_ni && flush_step && !flush_valid);                            // an empty slot passed
  cover property (@(posedge clk_i) rst_ni && ticks_i > 1 && state_q == H_ACCESS);                   // a warped access
endmodule

bind had had_cover u_cover (.*);
