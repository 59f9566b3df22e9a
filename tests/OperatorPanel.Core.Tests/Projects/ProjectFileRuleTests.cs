using System.Text.Json.Nodes;
using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Projects;

namespace OperatorPanel.Core.Tests.Projects;

/// <summary>Well-formed files that break an S7-200 or panel rule: unknown CPU, addresses the CPU lacks, duplicates, Freeport line settings. Each asserts the location and the message.</summary>
public sealed class ProjectFileRuleTests
{
    [Fact]
    public void Parse_UnknownCpu_ReportsTheModel()
    {
        BadFile.Expect(t => t.Station()["cpu"]!["model"] = "225", "$.stations[0].cpu.model", "unknown CPU model '225'; supported: 221, 222, 224, 224XP, 226");
    }

    [Fact]
    public void Parse_RevisionTheModelNeverHad_NamesTheRevisionsItHas()
    {
        BadFile.Expect(
            t => (t.Station()["cpu"]!["model"], t.Station()["cpu"]!["revision"]) = ("224XP", "early"),
            "$.stations[0].cpu.revision",
            "CPU 224XP has no early revision; it exists as: current");
    }

    [Fact]
    public void Parse_AddressPastTheCpuVMemory_ReportsTheLastByte()
    {
        BadFile.Expect(t => t.Station()["tags"]![1]!["address"] = "VW8191", "$.stations[0].tags[1].address", "VW8191 ends at VB8192, past the last V byte VB8191 of CPU 224");
    }

    [Fact]
    public void Parse_SameAddressOnAnEarlierRevision_IsCheckedAgainstThatStationsCpu()
    {
        var tree = SampleProject.Tree();
        tree.Station()["tags"]![0]!["address"] = "VD6000";
        ProjectFile.Parse(tree.ToJsonString()).Ok.Should().BeTrue();

        tree.Station()["cpu"]!["revision"] = "early";

        BadFile.SingleProblem(tree.ToJsonString()).Location.Should().Be("$.stations[0].tags[0].address");
    }

    [Fact]
    public void Parse_BadAddressSyntax_ReportsTheParserReason()
    {
        BadFile.Expect(t => t.Station()["alarms"]![0]!["flag"] = "M2.8", "$.stations[0].alarms[0].flag", "'M2.8': bit number 8 is outside 0-7");
    }

    [Fact]
    public void Parse_InputThatIsAnOutputBit_SaysInputsAreIBits()
    {
        BadFile.Expect(t => t.Station()["inputs"]![3]!["address"] = "Q0.3", "$.stations[0].inputs[3].address", "an input is an I bit such as I0.0, not Q0.3");
    }

    [Fact]
    public void Parse_OutputThatIsAByte_SaysOutputsAreQBits()
    {
        BadFile.Expect(t => t.Station()["outputs"]![0]!["address"] = "QB0", "$.stations[0].outputs[0].address", "an output is a Q bit such as Q0.0, not QB0");
    }

    [Fact]
    public void Parse_WritableTagOnInputs_IsRefusedForWriting()
    {
        BadFile.Expect(
            t => t.Station()["tags"]!.AsArray().Add(new JsonObject { ["symbol"] = "Inputs", ["address"] = "IB0", ["writable"] = true }),
            "$.stations[0].tags[11].address",
            "IB0: inputs are read from the field; the panel never writes them");
    }

    [Fact]
    public void Parse_TagOnSequenceRelays_SaysTheLinkDoesNotServeIt()
    {
        BadFile.Expect(t => t.Station()["tags"]![0]!["address"] = "SD0", "$.stations[0].tags[0].address", "SD0: the Freeport link reads only I, Q, M and V: its handler leaves S bits out to stay small; copy the S bits to V in the PLC program (MOVB SB0, VB100) and watch that, or read the station over PPI (\"protocol\": \"ppi\"), which reads S bits");
    }

    [Theory]
    [InlineData(3, "bool", "bool cannot show VD120, a double word; bool is for bits")]
    [InlineData(1, "float", "float cannot show VW104, a word; float is for double words (VD, MD)")]
    [InlineData(10, "hex", "hex cannot show M0.0, a bit; hex is for bytes, words and double words; use bool for a bit")]
    public void Parse_FormatNotFittingTheWidth_ReportsTheFormat(int tag, string format, string message)
    {
        BadFile.Expect(t => t.Station()["tags"]![tag]!["format"] = format, $"$.stations[0].tags[{tag}].format", message);
    }

    [Fact]
    public void Parse_DuplicateSymbol_NamesTheFirstUse()
    {
        BadFile.Expect(t => t.Station()["tags"]![0]!["symbol"] = "startbutton", "$.stations[0].tags[0].symbol", "symbol 'startbutton' is already used by $.stations[0].inputs[1]");
    }

    [Fact]
    public void Parse_SameInputListedTwice_NamesTheFirstEntry()
    {
        BadFile.Expect(t => t.Station()["inputs"]![5]!["address"] = "I0.0", "$.stations[0].inputs[5].address", "I0.0 is already listed by $.stations[0].inputs[0]");
    }

    [Fact]
    public void Parse_DuplicateStationAddressOnOnePort_IsReportedAtTheSecondStation()
    {
        BadFile.Expect(t => t.AddStation("Capper", 2, "COM3"), "$.stations[1].address", "station address 2 is already used on COM3 by $.stations[0]");
    }

    [Fact]
    public void Parse_SameStationAddressOnAnotherPort_IsFine()
    {
        var tree = SampleProject.Tree();
        tree.AddStation("Capper", 2, "COM4");

        ProjectFile.Parse(tree.ToJsonString()).Errors.Should().BeEmpty();
    }

    [Fact]
    public void Parse_DuplicateStationName_NamesTheFirstStation()
    {
        BadFile.Expect(t => t.AddStation("FILLER", 3, "COM3"), "$.stations[1].name", "station name 'FILLER' is already used by $.stations[0]");
    }

    [Fact]
    public void Parse_TwoStationsOnOnePortWithDifferentBaud_ReportsTheSharedBus()
    {
        BadFile.Expect(
            t => t.AddStation("Capper", 3, "com3")["link"]!["baud"] = 19200,
            "$.stations[1].link",
            "com3 is set to 9600 8N1 cable by $.stations[0]; the stations on one port share one bus and its settings");
    }

    [Theory]
    [InlineData(0)]
    [InlineData(127)]
    [InlineData(-5)]
    public void Parse_StationAddressOutside1To126_IsRefused(int address)
    {
        BadFile.Expect(t => t.Station()["address"] = address, "$.stations[0].address", $"station address {address} is outside 1-126");
    }

    [Fact]
    public void Parse_BaudTheCpuCannotRun_ListsTheFreeportRates()
    {
        BadFile.Expect(t => t.Station()["link"]!["baud"] = 14400, "$.stations[0].link.baud", "CPU 224 cannot run Freeport at 14400 baud; use one of 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200");
    }

    [Fact]
    public void Parse_TwoStopBits_SaysFreeportSendsOne()
    {
        BadFile.Expect(t => t.Station()["link"]!["stopBits"] = 2, "$.stations[0].link.stopBits", "2 stop bits: S7-200 Freeport always sends one stop bit; use 1");
    }

    [Fact]
    public void Parse_NineDataBits_IsRefused()
    {
        BadFile.Expect(t => t.Station()["link"]!["dataBits"] = 9, "$.stations[0].link.dataBits", "9 data bits: a Freeport character has 7 or 8 (SMB30 bit 5)");
    }

    [Fact]
    public void Parse_UnknownParityAndLinkKind_ListTheWords()
    {
        var tree = SampleProject.Tree();
        tree.Station()["link"]!["parity"] = "mark";
        tree.Station()["link"]!["kind"] = "wifi";

        ProjectFile.Parse(tree.ToJsonString()).Errors.Should().Equal(
            new ProjectFileError("$.stations[0].link.parity", "unknown parity 'mark'; use none, even, odd"),
            new ProjectFileError("$.stations[0].link.kind", "unknown kind 'wifi'; use cable, radioModule"));
    }

    [Fact]
    public void Parse_EmptyPort_IsRefused()
    {
        BadFile.Expect(t => t.Station()["link"]!["port"] = " ", "$.stations[0].link.port", "the serial port name is empty; write e.g. COM3 or /dev/ttyUSB0");
    }

    [Fact]
    public void Parse_RefreshPeriodAboveAMinute_IsRefused()
    {
        BadFile.Expect(t => t["refresh"]!["minimumPeriodMs"] = 60001, "$.refresh.minimumPeriodMs", "minimum period 60001 ms is outside 0-60000 ms");
    }

    [Fact]
    public void Parse_UnknownRefreshMode_NamesBothModes()
    {
        BadFile.Expect(t => t["refresh"]!["mode"] = "sometimes", "$.refresh.mode", "unknown refresh mode 'sometimes'; use continuous or triggered");
    }

    [Fact]
    public void Parse_AlarmOnAByteOrWithoutText_IsRefused()
    {
        var tree = SampleProject.Tree();
        tree.Station()["alarms"]![0]!["flag"] = "MB2";
        tree.Station()["alarms"]![1]!["text"] = "";

        ProjectFile.Parse(tree.ToJsonString()).Errors.Should().Equal(
            new ProjectFileError("$.stations[0].alarms[0].flag", "an alarm flag is a bit such as M2.0; MB2 is a byte"),
            new ProjectFileError("$.stations[0].alarms[1].text", "the alarm text is empty; the operator would see a blank message"));
    }

    [Fact]
    public void Parse_NoStations_IsRefused()
    {
        BadFile.Expect(t => t["stations"] = new JsonArray(), "$.stations", "a project needs at least one station");
    }
}
