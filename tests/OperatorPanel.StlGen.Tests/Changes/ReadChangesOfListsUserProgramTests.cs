using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Tests.Differential;
using OperatorPanel.StlGen.Tests.Merge.UserPrograms;

namespace OperatorPanel.StlGen.Tests.Changes;

/// <summary>
/// 09 READ CHANGES OF LISTS while a user's program changes a list's byte every scan, between the handler's slices
/// (the reference model cannot know those bytes): after every reply the panel's view of each list, every entry applied
/// and every REREAD list read whole with 08, equals the handler's copy in V memory, and the counting byte's changes are
/// reported.
/// </summary>
public sealed class ReadChangesOfListsUserProgramTests
{
    [Fact]
    public void ReadChangesOfLists_ProgramIncrementsAListByteEveryScan_PanelViewAlwaysEqualsTheCopies()
    {
        // VB50 counts scans: list 1 = VB48-VB53, list 2 = VB60-VB63 (left alone). Copies: list 1 at copy byte 0, list 2 at 6.
        var options = UserProgram.Cpu224;
        var harness = new DifferentialHarness(options, new Random(5), UserProgram.Ob1("LD     SM0.0", "INCB   VB50"));
        var panel = new Panel(harness, options.Station);
        panel.Define(1, new ReadItem(ProtocolArea.V, 48, 6));
        panel.Define(2, new ReadItem(ProtocolArea.V, 60, 4));
        panel.ReadWhole(1);
        panel.ReadWhole(2);
        var copies = harness.ReservedFirst + StlGen.Handler.HandlerLayout.CopyArea;
        var reported = 0;

        for (var n = 0; n < 10; n++)
        {
            var reply = panel.ReadChangesOfLists(0b0011);
            foreach (var reread in reply.Lists.Where(l => l.Reread))
            {
                panel.ReadWhole(reread.List);
            }

            var copy = harness.Interpreted(ProtocolArea.V).AsSpan(copies, 10).ToArray();
            panel.Known[1].Concat(panel.Known[2]).Should().Equal(copy, $"exchange {n}: the copies hold what the replies reported");
            panel.Known[2].Should().Equal(harness.Interpreted(ProtocolArea.V).AsSpan(60, 4).ToArray());
            reported += reply.Lists[0].Changes.Any(c => c.Index == 2) ? 1 : 0;
        }

        reported.Should().BeGreaterThan(8, "the counting byte changed between every two replies");
    }

    /// <summary>The panel side without the reference model (it cannot know VB50).</summary>
    private sealed class Panel(DifferentialHarness harness, int station)
    {
        private readonly Core.Addressing.Station _station = new(station);
        private byte _sequence;

        public Dictionary<int, byte[]> Known { get; } = [];

        public void Define(int list, ReadItem item) =>
            Send(new DefineListRequest(_station, ++_sequence, list, [item])).Should().BeOfType<DefineListResponse>();

        public void ReadWhole(int list)
        {
            var reply = Send(new ReadChangesRequest(_station, ++_sequence, list, true)).Should().BeOfType<ReadChangesResponse>().Subject;
            Known[list] = [.. reply.Data];
        }

        public ReadChangesOfListsResponse ReadChangesOfLists(byte mask)
        {
            var reply = Send(new ReadChangesOfListsRequest(_station, ++_sequence, mask)).Should().BeOfType<ReadChangesOfListsResponse>().Subject;
            foreach (var entry in reply.Lists.Where(l => !l.Reread))
            {
                foreach (var change in entry.Changes)
                {
                    Known[entry.List][change.Index] = change.Value;
                }
            }

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
