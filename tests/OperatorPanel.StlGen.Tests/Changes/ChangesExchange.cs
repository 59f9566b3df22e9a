using System.Collections.Immutable;
using System.Text;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Protocol;
using OperatorPanel.StlGen.Tests.Differential;

namespace OperatorPanel.StlGen.Tests.Changes;

/// <summary>
/// One request to the interpreted handler and the reference model: both answers must be the same characters; the
/// handler's answer comes back decoded (null for silence). The PC side of READ CHANGES is kept here too: what the panel
/// knows of each list after applying every good reply, which must always equal the handler's copy.
/// </summary>
internal sealed class ChangesExchange(DifferentialHarness harness, int station)
{
    private readonly Dictionary<int, ImmutableArray<byte>> _known = [];
    private byte _sequence;

    public Station Station { get; } = new(station);

    public byte NextSequence() => ++_sequence;

    /// <summary>What the panel holds for <paramref name="list"/> from its READ CHANGES replies.</summary>
    public ImmutableArray<byte> Known(int list) => _known[list];

    public PlcResponse? Send(PlcRequest request)
    {
        var (stl, reference) = harness.Exchange([WireChunk.Now(RequestCodec.Encode(request))]);
        stl.Should().Be(reference, $"the handler answers {request} like the reference model");
        if (stl.Length == 0)
        {
            return null;
        }

        ResponseCodec.TryDecode(Encoding.ASCII.GetBytes(stl), request, out var response, out var error).Should().BeTrue($"'{stl}' decodes ({error})");
        if (response is ReadChangesResponse changes && request is ReadChangesRequest asked)
        {
            changes.TryApply(_known.GetValueOrDefault(asked.List, []).AsSpan(), out var now).Should().BeTrue("every INDEX lies inside the list");
            _known[asked.List] = now;
        }

        if (response is ReadChangesOfListsResponse lists)
        {
            foreach (var entry in lists.Lists)
            {
                Apply(entry);
            }
        }

        return response;
    }

    /// <summary>Whether the panel holds <paramref name="list"/>'s data (a REREAD entry leaves it to an 08 FULL).</summary>
    public bool Knows(int list) => _known.ContainsKey(list);

    public ReadChangesOfListsResponse ReadChangesOfLists(byte mask) =>
        Send(new ReadChangesOfListsRequest(Station, NextSequence(), mask)).Should().BeOfType<ReadChangesOfListsResponse>().Subject;

    /// <summary>PC rule 3 and 08's rules: a REREAD list is unknown until read whole; pairs apply to the last good data.</summary>
    private void Apply(ListChanges entry)
    {
        if (entry.Reread)
        {
            _known.Remove(entry.List);
            return;
        }

        entry.TryApply(_known[entry.List].AsSpan(), out var now).Should().BeTrue("every INDEX lies inside the list");
        _known[entry.List] = now;
    }

    /// <summary>A frame the codec would not build (bad FLAGS, wrong length): both answers, undecoded.</summary>
    public (string Stl, string Reference) Raw(FreeportFrame frame) => harness.Exchange([WireChunk.Now(FrameCodec.Encode(frame))]);

    public ReadChangesResponse ReadChanges(int list, bool full = false) =>
        Send(new ReadChangesRequest(Station, NextSequence(), list, full)).Should().BeOfType<ReadChangesResponse>().Subject;

    public void Define(int list, params ReadItem[] items) =>
        Send(new DefineListRequest(Station, NextSequence(), list, [.. items])).Should().BeOfType<DefineListResponse>();

    public ProtocolError Error(PlcRequest request) => Send(request).Should().BeOfType<ErrorResponse>().Subject.Error;
}
