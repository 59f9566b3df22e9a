namespace OperatorPanel.Stl;

/// <summary>
/// One entry of a block's variable table, <c>name:TYPE;</c> with its optional comment. The type word is kept as
/// written, upper case (BOOL, BYTE, WORD, INT, DWORD, DINT, REAL, ...).
/// </summary>
public sealed record AwlVariable(string Name, string Type, AwlVariableSection Section, string Comment, int Line);
