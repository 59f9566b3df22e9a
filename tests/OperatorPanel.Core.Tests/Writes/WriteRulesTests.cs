using System.Collections.Immutable;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Projects;
using OperatorPanel.Core.Transport;
using OperatorPanel.Core.Writes;
using OperatorPanel.TestKit;

namespace OperatorPanel.Core.Tests.Writes;

/// <summary>
/// The project's write rules, the same for <c>opanel write</c> and the Memory window: a read-only tag binds every byte it
/// has, however a write names it, and the station's handler keeps its own V bytes.
/// </summary>
public sealed class WriteRulesTests
{
    private static readonly ProjectStation Filler = Station(
        [Tag("TankLevel", "VW150", writable: false), Tag("Running", "V160.2", writable: false), Tag("Outputs", "QB0", writable: false), Tag("Recipe", "VB110", writable: true)],
        outputs: [new IoSymbol("Pump", PlcAddress.Parse("Q0.1"), string.Empty)]);

    [Theory]
    [InlineData("VW150", "VW150 is part of tag TankLevel, which the project marks read-only")]
    [InlineData("VB151", "VB151 is part of tag TankLevel (VW150), which the project marks read-only")]
    [InlineData("V150.3", "V150.3 is part of tag TankLevel (VW150), which the project marks read-only")]
    [InlineData("VD148", "VD148 overlaps tag TankLevel (VW150), which the project marks read-only")]
    [InlineData("VW151", "VW151 overlaps tag TankLevel (VW150), which the project marks read-only")]
    [InlineData("VB160", "VB160 overlaps tag Running (V160.2), which the project marks read-only")]
    [InlineData("V160.2", "V160.2 is part of tag Running, which the project marks read-only")]
    [InlineData("QB0", "QB0 is part of tag Outputs, which the project marks read-only")]
    public void Refusal_AnyByteOfAReadOnlyTag_IsRefusedNamingTheTag(string address, string message)
    {
        WriteRules.Refusal(PlcAddress.Parse(address), Filler).Should().Be(message);
    }

    [Theory]
    [InlineData("VB149")] //   just below TankLevel
    [InlineData("VW152")] //   just above it
    [InlineData("V160.3")] //  WRITE BITS changes its own bit: Running's bit stays
    [InlineData("VB110")] //   a writable tag
    [InlineData("Q0.1")] //    an output the project lists: the Output window switches it, whatever tag shows QB0
    [InlineData("MW150")] //   another area
    public void Refusal_BytesNoReadOnlyTagHas_IsNull(string address)
    {
        WriteRules.Refusal(PlcAddress.Parse(address), Filler).Should().BeNull();
    }

    [Theory]
    [InlineData(false, "VB7586", "VB7586 is in the handler's own V bytes VB7586-VB8191 (where generate puts the full handler's buffer, work bytes and list by default")]
    [InlineData(true, "VB8014", "VB8014 is in the handler's own V bytes VB8014-VB8191 (where generate puts the compact handler's buffer and work bytes by default")]
    public void Refusal_FreeportStation_RefusesItsHandlersOwnVBytes(bool compact, string address, string message)
    {
        WriteRules.Refusal(PlcAddress.Parse(address), Filler with { Compact = compact }).Should().StartWith(message);
    }

    [Fact]
    public void Refusal_CompactStation_WritesTheBytesOnlyTheFullHandlerWouldKeep()
    {
        WriteRules.Refusal(PlcAddress.Parse("VB8000"), Filler with { Compact = true }).Should().BeNull();
    }

    [Fact]
    public void Refusal_PpiStation_HasNoHandlerBytes()
    {
        var ppi = Filler with { Link = Filler.Link with { Protocol = LinkProtocol.Ppi } };

        WriteRules.Refusal(PlcAddress.Parse("VB8000"), ppi).Should().BeNull();
        WriteRules.Refusal(PlcAddress.Parse("VB151"), ppi).Should().Contain("tag TankLevel", "the project's read-only tags hold on every link");
    }

    [Fact]
    public void Refusal_WithoutProject_KnowsNoTagsAndTakesTheFullHandler()
    {
        var cpu = Some.Cpu(CpuModel.Cpu224);

        WriteRules.Refusal(PlcAddress.Parse("VW150"), LinkProtocol.Freeport, cpu, station: null).Should().BeNull();
        WriteRules.Refusal(PlcAddress.Parse("VB8000"), LinkProtocol.Freeport, cpu, station: null).Should().StartWith("VB8000 is in the handler's own V bytes VB7586-VB8191");
        WriteRules.Refusal(PlcAddress.Parse("VB8000"), LinkProtocol.Freeport, cpu: null, station: null).Should().BeNull("without a CPU the size of V is unknown");
    }

    [Fact]
    public void Refusal_HandlerTheProjectMoved_WritesTheTopOfVAndRefusesTheMovedBytes()
    {
        var moved = Filler with { HandlerVFirst = 1000 };

        WriteRules.Refusal(PlcAddress.Parse("VB8000"), moved).Should().BeNull("the handler is not at the top of V: those bytes are the program's");
        WriteRules.Refusal(PlcAddress.Parse("VW1000"), moved).Should().Be(
            "VW1000 is in the handler's own V bytes VB1000-VB1605 (where the project's \"handlerVFirst\" puts the full handler's buffer, "
            + "work bytes and list; IDENTIFY says where a station's are)");
    }

    [Fact]
    public void Refusal_StationGivenApartFromItsLink_TakesTheHandlerWhereTheProjectPutsIt()
    {
        // opanel write --project --cpu: the CPU given, the station's handler place from the project.
        var moved = Filler with { HandlerVFirst = 1000 };

        WriteRules.Refusal(PlcAddress.Parse("VB1605"), LinkProtocol.Freeport, Some.Cpu(CpuModel.Cpu224), moved).Should().StartWith("VB1605 is in the handler's own V bytes VB1000-VB1605 ");
        WriteRules.Refusal(PlcAddress.Parse("VB7586"), LinkProtocol.Freeport, Some.Cpu(CpuModel.Cpu224), moved).Should().BeNull();
    }

    [Theory]
    [InlineData("Speed", "VW150", "tag Speed (VW150) is writable, but its bytes VB150-VB151 are also in tag TankLevel (VW150)")]
    [InlineData("Speed", "VD148", "tag Speed (VD148) is writable, but its bytes VB150-VB151 are also in tag TankLevel (VW150)")]
    [InlineData("Speed", "VW151", "tag Speed (VW151) is writable, but its byte VB151 is also in tag TankLevel (VW150)")]
    [InlineData("Flag", "V151.0", "tag Flag (V151.0) is writable, but its byte VB151 is also in tag TankLevel (VW150)")]
    [InlineData("Flag", "V160.2", "tag Flag (V160.2) is writable, but its bit V160.2 is also in tag Running (V160.2)")]
    public void TagProblem_WritableTagSharingBytesWithAReadOnlyTag_NamesBothTagsAndTheSharedBytes(string symbol, string address, string start)
    {
        var tag = Tag(symbol, address, writable: true);
        var station = Filler with { Tags = Filler.Tags.Add(tag) };

        WriteRules.TagProblem(tag, station).Should().StartWith(start).And.EndWith(
            ", which the project marks read-only: the panel refuses every write to it; set \"writable\": false on one of them, or move one");
    }

    [Theory]
    [InlineData(null, "VW8000", "VW8000 is in the handler's own V bytes VB7586-VB8191 (where generate puts the full handler's buffer, work bytes and list by default")]
    [InlineData(1000, "VW1000", "VW1000 is in the handler's own V bytes VB1000-VB1605 (where the project's \"handlerVFirst\" puts the full handler's buffer, work bytes and list")]
    public void TagProblem_WritableTagInTheHandlersOwnVBytes_NamesTheTagAndTheRange(int? vFirst, string address, string reason)
    {
        var tag = Tag("Speed", address, writable: true);
        var station = Filler with { Tags = Filler.Tags.Add(tag), HandlerVFirst = vFirst };

        WriteRules.TagProblem(tag, station).Should().Be(
            $"tag Speed ({address}) is writable, but {reason}; IDENTIFY says where a station's are): the panel refuses every write to it; "
            + "set \"writable\": false, move the tag, or move the handler (the station's \"handlerVFirst\", which generate uses, then regenerate)");
    }

    [Theory]
    [InlineData("VW152", false, null)] //    beside TankLevel
    [InlineData("V160.3", false, null)] //   another bit of Running's byte: WRITE BITS leaves Running's bit alone
    [InlineData("VW8000", false, 1000)] //   the top of V with the handler moved to VB1000
    [InlineData("VW8000", true, null)] //    a PPI station has no handler
    public void TagProblem_WritableTagTheRulesLetBeWritten_IsNull(string address, bool ppi, int? vFirst)
    {
        var tag = Tag("Speed", address, writable: true);
        var link = Filler.Link with { Protocol = ppi ? LinkProtocol.Ppi : LinkProtocol.Freeport };
        var station = Filler with { Tags = Filler.Tags.Add(tag), Link = link, HandlerVFirst = vFirst };

        WriteRules.TagProblem(tag, station).Should().BeNull();
    }

    [Fact]
    public void TagProblem_ReadOnlyTagInTheHandlersBytes_IsNull()
    {
        // Reading the handler's bytes is allowed (a technician may watch its step byte); only a write would be refused.
        var tag = Tag("Step", "VB8000", writable: false);

        WriteRules.TagProblem(tag, Filler with { Tags = Filler.Tags.Add(tag) }).Should().BeNull();
    }

    private static ProjectStation Station(ImmutableArray<ProjectTag> tags, ImmutableArray<IoSymbol> outputs) =>
        new("Filler", new Station(2), Some.Cpu(CpuModel.Cpu224), Some.SerialSettings(), [], outputs, tags, []);

    private static ProjectTag Tag(string symbol, string address, bool writable)
    {
        var at = PlcAddress.Parse(address);
        return new ProjectTag(symbol, at, DisplayFormats.DefaultFor(at), writable, string.Empty);
    }
}
