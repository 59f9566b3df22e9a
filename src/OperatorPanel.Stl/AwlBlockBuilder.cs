using System.Collections.Immutable;

namespace OperatorPanel.Stl;

/// <summary>Collects one block while <see cref="AwlReader"/> walks its lines.</summary>
internal sealed class AwlBlockBuilder(AwlBlockKind kind, string name, int number, int startLine, bool hasName)
{
    private readonly ImmutableArray<string>.Builder _comments = ImmutableArray.CreateBuilder<string>();
    private readonly ImmutableArray<AwlVariable>.Builder _variables = ImmutableArray.CreateBuilder<AwlVariable>();
    private readonly ImmutableArray<AwlNetwork>.Builder _networks = ImmutableArray.CreateBuilder<AwlNetwork>();
    private NetworkBuilder? _network;
    private AwlVariableSection? _section;

    public AwlBlockKind Kind { get; } = kind;

    public string Name { get; } = name;

    public string Title { get; set; } = string.Empty;

    public bool InBody { get; set; }

    public bool InVariables => _section is not null;

    public static AwlVariableSection? SectionOf(string word) => word switch
    {
        "VAR_INPUT" => AwlVariableSection.Input,
        "VAR_IN_OUT" => AwlVariableSection.InOut,
        "VAR_OUTPUT" => AwlVariableSection.Output,
        "VAR" or "VAR_TEMP" => AwlVariableSection.Temp,
        _ => null,
    };

    public void OpenSection(AwlVariableSection section) => _section = section;

    public void CloseSection() => _section = null;

    public void AddVariable(string variable, string type, string comment, int line) =>
        _variables.Add(new AwlVariable(variable, type, _section!.Value, comment, line));

    /// <summary>Comment lines go to the network being read until its first instruction, else to the block header.</summary>
    public void AddComment(string comment)
    {
        if (_network is { Instructions.Count: 0 })
        {
            _network.Comments.Add(comment);
        }
        else if (!InBody)
        {
            _comments.Add(comment);
        }
    }

    public void OpenNetwork(int number, string title, int line)
    {
        CloseNetwork();
        _network = new NetworkBuilder(number, title, line);
    }

    public void AddInstruction(AwlInstruction instruction, int line)
    {
        _network ??= new NetworkBuilder(0, string.Empty, line);
        _network.Instructions.Add(instruction);
    }

    public AwlBlock Build(int endLine)
    {
        CloseNetwork();
        return new AwlBlock(
            Kind, Name, number, Title, _comments.ToImmutable(), _variables.ToImmutable(), _networks.ToImmutable(), startLine, endLine)
        { HasName = hasName };
    }

    private void CloseNetwork()
    {
        if (_network is not null)
        {
            _networks.Add(new AwlNetwork(
                _network.Number, _network.Title, _network.Comments.ToImmutable(), _network.Instructions.ToImmutable(), _network.Line));
            _network = null;
        }
    }

    private sealed class NetworkBuilder(int number, string title, int line)
    {
        public int Number { get; } = number;

        public string Title { get; } = title;

        public int Line { get; } = line;

        public ImmutableArray<string>.Builder Comments { get; } = ImmutableArray.CreateBuilder<string>();

        public ImmutableArray<AwlInstruction>.Builder Instructions { get; } = ImmutableArray.CreateBuilder<AwlInstruction>();
    }
}
