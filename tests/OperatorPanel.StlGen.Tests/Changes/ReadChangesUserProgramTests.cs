using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Tests.Differential;
using OperatorPanel.StlGen.Tests.Merge.UserPrograms;

namespace OperatorPanel.StlGen.Tests.Changes;

/// <summary>
/// READ CHANGES while a user's program changes the list's bytes every scan, between the handler's slices: the
/// reference model cannot know those bytes, so the proof is the protocol's promise itself. After every reply the
/// panel's view (every reply applied) equals the handler's copy in V memory, and the counting byte's changes are
/// reported; the bytes the program leaves alone match the memory.
/// </summary>
public sealed class ReadChangesUserProgramTests
{
    [Fact]
    public void ReadChanges_ProgramIncrementsAListByteEveryScan_PanelViewAlwaysEqualsTheCopy()
    {
        // VB50 counts scans; VB51-VB53 stay.
        var program = UserProgram.Ob1("LD     SM0.0", "INCB   VB50");
        var options = UserProgram.Cpu224;
        var harness = new DifferentialHarness(options, new Random(5), program);
        var panel = new Unchecked(harness, options.Station);
        panel.Define(new ReadItem(ProtocolArea.V, 48, 6));
        var copyStart = harness.ReservedFirst + StlGen.Handler.HandlerLayout.CopyArea;
        var reported = 0;

        for (var n = 0; n < 12; n++)
        {
            var reply = panel.ReadChanges(full: n == 0);
            var copy = harness.Interpreted(ProtocolArea.V).AsSpan(copyStart, 6).ToArray();

            panel.Known.Should().Equal(copy, $"exchange {n}: the copy holds what the replies reported");
            reported += reply.Full || reply.Changes.Any(c => c.Index == 2) ? 1 : 0;
            panel.Known.Where((_, i) => i != 2).Should().Equal(harness.Interpreted(ProtocolArea.V).AsSpan(48, 6).ToArray().Where((_, i) => i != 2));
        }

        reported.Should().BeGreaterThan(8, "the counting byte changed between every two replies");
    }

    /// <summary>The panel side without the reference model (it cannot know VB50).</summary>
    private sealed class Unchecked(DifferentialHarness harness, int station)
    {
        private readonly Core.Addressing.Station _station = new(station);
        private byte _sequence;

        public byte[] Known { get; private set; } = [];

        public void Define(ReadItem item) =>
            Send(new DefineListRequest(_station, ++_sequence, 1, [item])).Should().BeOfType<DefineListResponse>();

        public ReadChangesResponse ReadChanges(bool full)
        {
            var request = new ReadChangesRequest(_station, ++_sequence, 1, full);
            var reply = Send(request).Should().BeOfType<ReadChangesResponse>().Subject;
            reply.TryApply(Known, out var now).Should().BeTrue();
            Known = [.. now];
            return reply;
        }

        private PlcResponse Send(PlcRequest request)
        {
            var (stl, _) = harness.Exchange([WireChunk.Now(RequestCodec.Encode(request))]);
            ResponseCodec.TryDecode(System.Text.Encoding.ASCII.GetBytes(stl), request, out var response, out var error).Should().BeTrue($"'{stl}' ({error})");
            return response;
        }
    }
}
